#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {
namespace {

constexpr int MAX_DIMENSION = 31;
constexpr double MIN_WIDTH = 300;
constexpr double MAX_WIDTH = 100000;
/** At most this many tick intervals on an axis (so at most 7 labels). */
constexpr int MAX_TICK_INTERVALS = 6;
constexpr std::size_t MAX_MARKERS_PER_DIMENSION = 1000;

constexpr std::array<const char*, 6> DIMENSION_COLOURS = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"};
constexpr const char* ESSENTIAL_COLOUR = "#d62728";
/** Fill opacities of persistence diagram markers standing for 1, 2-4, 5-16, 17+
 * points. */
constexpr std::array<const char*, 4> MARKER_OPACITIES = {"0.7", "0.8", "0.9", "1"};

constexpr const char* STYLE = ".title{font-size:16px;font-weight:bold}"
                              ".panel-label{font-weight:bold;fill:#222}"
                              ".tick-label{font-size:11px;fill:#333}"
                              ".axis-title{fill:#333}"
                              ".note{font-size:11px;font-style:italic;fill:#555}"
                              ".panel{fill:#f8f8f8;stroke:#ccc}"
                              ".grid{stroke:#e2e2e2}"
                              ".axis{stroke:#333}"
                              ".below-diagonal{fill:#ececec}"
                              ".diagonal{stroke:#888}"
                              ".infinity{stroke:#666;stroke-dasharray:6 4}"
                              ".infinity-label{font-size:16px;fill:#333}"
                              ".legend{fill:white;stroke:#ccc}"
                              ".cut{stroke:#d62728;stroke-width:1.5;"
                              "stroke-dasharray:5 3}"
                              ".cut-label{font-size:11px;fill:#d62728}";

// Text ------------------------------------------------------------------------

std::string
escapeXml (const std::string& text)
{
  std::string escaped;
  escaped.reserve (text.size());
  for (const char c : text) {
    switch (c) {
    case '&':
      escaped += "&amp;";
      break;
    case '<':
      escaped += "&lt;";
      break;
    case '>':
      escaped += "&gt;";
      break;
    case '"':
      escaped += "&quot;";
      break;
    case '\'':
      escaped += "&apos;";
      break;
    default:
      // Control characters other than tab and newlines are not allowed in XML.
      if (static_cast<unsigned char> (c) >= 0x20 || c == '\t' || c == '\n' || c == '\r')
        escaped += c;
    }
  }
  return escaped;
}

/** \a value with at most \a decimals digits after the point, trailing zeros dropped,
 * whatever the locale. */
std::string
formatFixed (double value, int decimals)
{
  char buffer[64];
  const auto end =
      std::to_chars (
          buffer, buffer + sizeof (buffer), value, std::chars_format::fixed, decimals)
          .ptr;
  std::string text (buffer, end);
  if (text.find ('.') != std::string::npos) {
    text.erase (text.find_last_not_of ('0') + 1);
    if (text.back() == '.')
      text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

/** \a value with \a digits significant digits, whatever the locale. */
std::string
formatSignificant (double value, int digits)
{
  char buffer[64];
  const auto end =
      std::to_chars (
          buffer, buffer + sizeof (buffer), value, std::chars_format::general, digits)
          .ptr;
  return std::string (buffer, end);
}

/** A pixel coordinate. */
std::string
px (double value)
{
  return formatFixed (value, 1);
}

/** \a count with thousands separators: 41,233. */
std::string
formatCount (std::size_t count)
{
  std::string digits = std::to_string (count);
  for (auto at = static_cast<std::ptrdiff_t> (digits.size()) - 3; at > 0; at -= 3)
    digits.insert (static_cast<std::size_t> (at), ",");
  return digits;
}

/** "3 intervals", "1 interval". */
std::string
formatCount (std::size_t count, const std::string& noun)
{
  return formatCount (count) + " " + noun + (count == 1 ? "" : "s");
}

std::string
formatInterval (const PersistenceInterval& interval)
{
  return "H" + std::to_string (interval.dimension) + " [" +
         formatSignificant (interval.birth, 6) + ", " +
         (interval.isEssential() ? "\u221e" : formatSignificant (interval.death, 6)) +
         ")";
}

// Data ------------------------------------------------------------------------

using IntervalsByDimension = std::vector<std::vector<PersistenceInterval>>;

/** Checks \a options and \a diagram, then returns the intervals of non-zero length
 * of each dimension from 0 to the largest dimension in the diagram. */
IntervalsByDimension
checkAndGroup (const PersistenceDiagram& diagram, const PlotOptions& options)
{
  if (options.max_bars_per_dimension == 0)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "max_bars_per_dimension must be at least 1");
  if (!(options.max_value >= 0 && std::isfinite (options.max_value)))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "max_value must be finite and not negative, got "
                             << options.max_value);
  if (!std::isnan (options.cut) && !(options.cut >= 0 && std::isfinite (options.cut)))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "cut must be finite and not negative (or NaN for none), got "
                             << options.cut);
  if (!(options.width >= MIN_WIDTH && options.width <= MAX_WIDTH))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "width must be from " << MIN_WIDTH << " to " << MAX_WIDTH
                                               << " pixels, got " << options.width);
  IntervalsByDimension intervals (1);
  for (const auto& interval : diagram) {
    if (interval.dimension < 0 || interval.dimension > MAX_DIMENSION ||
        !std::isfinite (interval.birth) || std::isnan (interval.death) ||
        interval.death < interval.birth)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "cannot plot the interval of dimension "
                               << interval.dimension << " [" << interval.birth << ", "
                               << interval.death << ")");
    const auto dimension = static_cast<std::size_t> (interval.dimension);
    if (intervals.size() <= dimension)
      intervals.resize (dimension + 1);
    if (interval.death > interval.birth)
      intervals[dimension].push_back (interval);
  }
  return intervals;
}

/** The filtration axis: from the smallest birth (or 0) to options.max_value, or to
 * the largest finite value when max_value is 0. */
std::pair<double, double>
filtrationRange (const IntervalsByDimension& intervals, const PlotOptions& options)
{
  double lo = 0, hi = 0;
  for (const auto& dimension : intervals)
    for (const auto& interval : dimension) {
      lo = std::min (lo, interval.birth);
      hi = std::max (hi, interval.isEssential() ? interval.birth : interval.death);
    }
  if (options.max_value > 0)
    hi = options.max_value;
  else if (!std::isnan (options.cut))
    hi = std::max (hi, options.cut);
  if (hi <= lo)
    hi = lo + 1;
  return {lo, hi};
}

// Axes ------------------------------------------------------------------------

/** A linear map from filtration values [lo, hi] to pixels [px_lo, px_hi] (values
 * outside are clamped), with round tick values: multiples of 1, 2 or 5 x 10^k. */
struct Axis {
  double lo, hi;
  double px_lo, px_hi;
  double step;
  std::vector<double> ticks;

  double
  toPixel (double value) const
  {
    const double t = (std::min (std::max (value, lo), hi) - lo) / (hi - lo);
    return px_lo + t * (px_hi - px_lo);
  }

  std::string
  label (double tick) const
  {
    const int exponent = static_cast<int> (std::floor (std::log10 (step) + 1e-9));
    if (exponent < -5 || exponent > 6)
      return formatSignificant (tick, 3);
    return formatFixed (tick, std::max (0, -exponent));
  }
};

/** The axis from \a lo to \a hi drawn from pixel \a px_lo to \a px_hi, with the
 * smallest round step giving at most MAX_TICK_INTERVALS intervals. */
Axis
makeAxis (double lo, double hi, double px_lo, double px_hi)
{
  const double least_step = (hi - lo) / MAX_TICK_INTERVALS;
  const double magnitude = std::pow (10.0, std::floor (std::log10 (least_step)));
  double step = 10 * magnitude;
  for (const double multiple : {1.0, 2.0, 5.0})
    if (multiple * magnitude >= least_step * (1 - 1e-9)) {
      step = multiple * magnitude;
      break;
    }
  Axis axis{lo, hi, px_lo, px_hi, step, {}};
  const auto first = static_cast<long long> (std::ceil (lo / step - 1e-9));
  const auto last = static_cast<long long> (std::floor (hi / step + 1e-9));
  for (long long i = first; i <= last; ++i)
    axis.ticks.push_back (static_cast<double> (i) * step);
  return axis;
}

// SVG elements ----------------------------------------------------------------

void
writeLine (
    std::ostream& out, double x1, double y1, double x2, double y2, const char* cls)
{
  out << "<line class=\"" << cls << "\" x1=\"" << px (x1) << "\" y1=\"" << px (y1)
      << "\" x2=\"" << px (x2) << "\" y2=\"" << px (y2) << "\"/>\n";
}

/** A text element; \a anchor is "middle", "end" or nullptr for the start. */
void
writeText (std::ostream& out,
           double x,
           double y,
           const std::string& text,
           const char* cls,
           const char* anchor = nullptr)
{
  out << "<text class=\"" << cls << "\" x=\"" << px (x) << "\" y=\"" << px (y) << "\"";
  if (anchor)
    out << " text-anchor=\"" << anchor << "\"";
  out << ">" << escapeXml (text) << "</text>\n";
}

void
writeRect (
    std::ostream& out, double x, double y, double width, double height, const char* cls)
{
  out << "<rect class=\"" << cls << "\" x=\"" << px (x) << "\" y=\"" << px (y)
      << "\" width=\"" << px (width) << "\" height=\"" << px (height) << "\"/>\n";
}

/** Header, style, white background and the title (titleHeight() pixels high). */
void
writeHeader (std::ostream& out, double width, double height, const std::string& title)
{
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << px (width)
      << "\" height=\"" << px (height) << "\" viewBox=\"0 0 " << px (width) << " "
      << px (height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  if (!title.empty())
    out << "<title>" << escapeXml (title) << "</title>\n";
  out << "<style>" << STYLE << "</style>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!title.empty())
    writeText (out, width / 2, 28, title, "title", "middle");
}

/** Height of the header written by writeHeader(). */
double
titleHeight (const std::string& title)
{
  return title.empty() ? 12 : 44;
}

/** Grid lines across the plot at the ticks of \a axis, from pixel \a from to \a to
 * along the other direction. */
void
writeGrid (std::ostream& out, const Axis& axis, bool horizontal, double from, double to)
{
  for (const double tick : axis.ticks) {
    const double at = axis.toPixel (tick);
    if (horizontal)
      writeLine (out, at, from, at, to, "grid");
    else
      writeLine (out, from, at, to, at, "grid");
  }
}

/** Axis line, ticks, tick labels and title, along the pixel row (\a horizontal) or
 * column \a position; labels are below or to the left. */
void
writeAxis (std::ostream& out,
           const Axis& axis,
           bool horizontal,
           double position,
           const std::string& title)
{
  if (horizontal)
    writeLine (out, axis.px_lo, position, axis.px_hi, position, "axis");
  else
    writeLine (out, position, axis.px_lo, position, axis.px_hi, "axis");
  for (const double tick : axis.ticks) {
    const double at = axis.toPixel (tick);
    if (horizontal) {
      writeLine (out, at, position, at, position + 5, "axis");
      writeText (out, at, position + 18, axis.label (tick), "tick-label", "middle");
    }
    else {
      writeLine (out, position - 5, at, position, at, "axis");
      writeText (out, position - 8, at + 4, axis.label (tick), "tick-label", "end");
    }
  }
  const double middle = (axis.px_lo + axis.px_hi) / 2;
  if (horizontal)
    writeText (out, middle, position + 36, title, "axis-title", "middle");
  else
    out << "<text class=\"axis-title\" text-anchor=\"middle\" transform=\"translate("
        << px (position - 46) << " " << px (middle) << ") rotate(-90)\">"
        << escapeXml (title) << "</text>\n";
}

/** \a title, followed by " (unit)" when \a unit is not empty. */
std::string
withUnit (const std::string& title, const std::string& unit)
{
  return unit.empty() ? title : title + " (" + unit + ")";
}

/** A red triangle pointing right from (\a x, \a y), the mark of an essential class. */
void
writeEssentialMarker (std::ostream& out, double x, double y, double half_height)
{
  out << "<path d=\"M" << px (x) << " " << px (y - half_height) << "l"
      << px (1.6 * half_height) << " " << px (half_height) << "l"
      << px (-1.6 * half_height) << " " << px (half_height) << "z\"/>\n";
}

// Barcode ---------------------------------------------------------------------

constexpr double BARCODE_MARGIN_LEFT = 30;
constexpr double BARCODE_MARGIN_RIGHT = 40;
constexpr double LEGEND_HEIGHT = 24;
constexpr double PANEL_LABEL_HEIGHT = 22;
/** A panel is at most about this high; bars get thinner down to MIN_PITCH. */
constexpr double BAR_AREA_HEIGHT = 400;
constexpr double MIN_PITCH = 2;
constexpr double MAX_PITCH = 12;
constexpr double PANEL_PADDING = 4;
constexpr double EMPTY_PANEL_HEIGHT = 28;
constexpr double NOTE_HEIGHT = 16;
constexpr double PANEL_GAP = 14;
/** Bars shorter than a pixel are widened to a pixel so that they remain visible. */
constexpr double MIN_BAR_WIDTH = 1;

double
length (const PersistenceInterval& interval)
{
  return interval.death - interval.birth;
}

/** The bars of one dimension to draw and the layout of its panel. */
struct BarcodePanel {
  std::vector<PersistenceInterval> bars; ///< Top to bottom.
  std::size_t total = 0;
  std::size_t hidden_essential = 0;
  double hidden_max_length = 0; ///< Longest finite bar not drawn.
  double top = 0;
  double pitch = 0;
  double height = 0;
};

/** Keeps the \a max_bars longest of \a intervals (essential first, then earlier
 * births), ordered by birth, then by decreasing length. */
BarcodePanel
selectBars (std::vector<PersistenceInterval> intervals, std::size_t max_bars)
{
  BarcodePanel panel;
  panel.total = intervals.size();
  if (intervals.size() > max_bars) {
    const auto kept = intervals.begin() + static_cast<std::ptrdiff_t> (max_bars);
    std::partial_sort (
        intervals.begin(), kept, intervals.end(), [] (const auto& a, const auto& b) {
          return length (a) > length (b) ||
                 (length (a) == length (b) && a.birth < b.birth);
        });
    for (auto interval = kept; interval != intervals.end(); ++interval) {
      if (interval->isEssential())
        ++panel.hidden_essential;
      else
        panel.hidden_max_length =
            std::max (panel.hidden_max_length, length (*interval));
    }
    intervals.erase (kept, intervals.end());
  }
  std::sort (intervals.begin(), intervals.end(), [] (const auto& a, const auto& b) {
    return a.birth < b.birth || (a.birth == b.birth && length (a) > length (b));
  });
  panel.bars = std::move (intervals);
  return panel;
}

/** "+ 41,233 shorter bars (length <= 0.0021) not drawn", the bound rounded up to two
 * significant digits. */
std::string
hiddenBarsNote (const BarcodePanel& panel)
{
  const std::size_t hidden = panel.total - panel.bars.size();
  if (panel.hidden_essential > 0)
    return "+ " + formatCount (hidden) +
           " bars not drawn: " + formatCount (panel.hidden_essential) +
           " essential born later, " + formatCount (hidden - panel.hidden_essential) +
           " finite";
  const double unit =
      std::pow (10.0, std::floor (std::log10 (panel.hidden_max_length)) - 1);
  const double bound = std::ceil (panel.hidden_max_length / unit - 1e-9) * unit;
  return "+ " + formatCount (hidden) + " shorter bars (length \u2264 " +
         formatSignificant (bound, 2) + ") not drawn";
}

/** The height of the row of \a bar in a panel of pitch \a pitch. */
double
rowPitch (const PersistenceInterval& bar, double pitch)
{
  return bar.isEssential() ? std::max (pitch, MIN_ESSENTIAL_PITCH) : pitch;
}

/** The dashed vertical line at options.cut from pixel row \a top to \a bottom,
 * labelled "cut" with the value and the unit above it. */
void
writeCut (std::ostream& out,
          const Axis& axis,
          const PlotOptions& options,
          double top,
          double bottom)
{
  const double x = axis.toPixel (options.cut);
  writeLine (out, x, top, x, bottom, "cut");
  const bool right_half = x > (axis.px_lo + axis.px_hi) / 2;
  std::string label = "cut " + formatSignificant (options.cut, 3);
  if (!options.unit.empty())
    label += " " + options.unit;
  writeText (out,
             right_half ? x - 4 : x + 4,
             top - 7,
             label,
             "cut-label",
             right_half ? "end" : nullptr);
}

void
writeBarcodePanel (std::ostream& out,
                   const BarcodePanel& panel,
                   std::size_t dimension,
                   const Axis& axis)
{
  const double left = axis.px_lo, right = axis.px_hi;
  writeText (out,
             left,
             panel.top - 7,
             "H" + std::to_string (dimension) + " (" +
                 formatCount (panel.total, "interval") + ")",
             "panel-label");
  writeRect (out, left, panel.top, right - left, panel.height, "panel");
  writeGrid (out, axis, true, panel.top, panel.top + panel.height);
  if (panel.bars.empty()) {
    writeText (out,
               (left + right) / 2,
               panel.top + panel.height / 2 + 4,
               "no intervals",
               "note",
               "middle");
    return;
  }

  out << "<g id=\"barcode-H" << dimension << "\" fill=\""
      << DIMENSION_COLOURS[dimension % DIMENSION_COLOURS.size()] << "\">\n";
  std::vector<double> centres; // of the essential bars
  double row_top = panel.top + PANEL_PADDING;
  for (const PersistenceInterval& bar : panel.bars) {
    const double pitch = rowPitch (bar, panel.pitch);
    const double bar_height =
        bar.isEssential() ? std::min (0.75 * pitch, pitch - 2) : 0.75 * pitch;
    const double start = axis.toPixel (bar.birth);
    const double end = bar.isEssential() ? right : axis.toPixel (bar.death);
    out << "<rect class=\"bar" << (bar.isEssential() ? " essential" : "") << "\" x=\""
        << px (start) << "\" y=\"" << px (row_top + (pitch - bar_height) / 2)
        << "\" width=\"" << px (std::max (end - start, MIN_BAR_WIDTH)) << "\" height=\""
        << px (bar_height) << "\"><title>" << formatInterval (bar)
        << "</title></rect>\n";
    if (bar.isEssential())
      centres.push_back (row_top + pitch / 2);
    row_top += pitch;
  }
  out << "</g>\n<g class=\"essential-marker\" fill=\"" << ESSENTIAL_COLOUR << "\">\n";
  const double half_height =
      std::min (std::max (0.5 * panel.pitch, 3.5), 0.5 * MIN_ESSENTIAL_PITCH);
  for (const double centre : centres)
    writeEssentialMarker (out, right, centre, half_height);
  out << "</g>\n";
  if (panel.total > panel.bars.size())
    writeText (
        out, left, panel.top + panel.height + 13, hiddenBarsNote (panel), "note");
}

// Persistence diagram ---------------------------------------------------------

constexpr double DIAGRAM_MARGIN_LEFT = 64;
constexpr double DIAGRAM_MARGIN_RIGHT = 24;
/** Distance from the dashed infinity line down to the top of the finite area. */
constexpr double INFINITY_GAP = 18;
constexpr double DIAGRAM_LEGEND_WIDTH = 190;
constexpr double DIAGRAM_LEGEND_ROW = 18;

/** A point (count 1) or a marker standing for \a count points at their mean. */
struct Marker {
  double x = 0, y = 0;
  std::size_t count = 0;
};

/** Merges \a points (in pixels) falling in the same cell of a square grid whose cells
 * are as small as possible, from \a cell pixels doubling up, so that at most
 * MAX_MARKERS_PER_DIMENSION markers remain; \a cell receives the size used. */
std::vector<Marker>
mergePoints (const std::vector<Marker>& points, double& cell)
{
  for (;; cell *= 2) {
    std::unordered_map<std::uint64_t, Marker> cells;
    for (const auto& point : points) {
      const std::uint64_t key = (static_cast<std::uint64_t> (point.x / cell) << 32) |
                                static_cast<std::uint32_t> (point.y / cell);
      Marker& marker = cells[key];
      marker.x += point.x;
      marker.y += point.y;
      ++marker.count;
      if (cells.size() > MAX_MARKERS_PER_DIMENSION)
        break;
    }
    if (cells.size() > MAX_MARKERS_PER_DIMENSION)
      continue;
    std::vector<Marker> markers;
    markers.reserve (cells.size());
    for (const auto& entry : cells) {
      const Marker& sum = entry.second;
      markers.push_back ({sum.x / sum.count, sum.y / sum.count, sum.count});
    }
    std::sort (markers.begin(), markers.end(), [] (const Marker& a, const Marker& b) {
      return a.y < b.y || (a.y == b.y && a.x < b.x);
    });
    return markers;
  }
}

/** Index into MARKER_OPACITIES: darker for markers standing for more points. */
std::size_t
opacityLevel (std::size_t count)
{
  std::size_t level = 0;
  for (std::size_t limit = 1; count > limit && level + 1 < MARKER_OPACITIES.size();
       limit *= 4)
    ++level;
  return level;
}

/** The marker of \a dimension centred on (\a x, \a y): circle, triangle, square,
 * diamond, then again. */
void
writeDimensionMarker (std::ostream& out, std::size_t dimension, double x, double y)
{
  switch (dimension % 4) {
  case 0:
    out << "<circle cx=\"" << px (x) << "\" cy=\"" << px (y) << "\" r=\"4\"/>\n";
    break;
  case 1:
    out << "<path d=\"M" << px (x) << " " << px (y - 5) << "l4.5 8h-9z\"/>\n";
    break;
  case 2:
    out << "<rect x=\"" << px (x - 3.5) << "\" y=\"" << px (y - 3.5)
        << "\" width=\"7\" height=\"7\"/>\n";
    break;
  default:
    out << "<path d=\"M" << px (x) << " " << px (y - 4.5)
        << "l4.5 4.5-4.5 4.5-4.5-4.5z\"/>\n";
  }
}

/** Opens the group of the markers of \a dimension, in its colour. */
void
openDimensionGroup (std::ostream& out, const std::string& id, std::size_t dimension)
{
  out << "<g id=\"" << id << "\" fill=\""
      << DIMENSION_COLOURS[dimension % DIMENSION_COLOURS.size()] << "\">\n";
}

} // namespace

void
writeBarcodeSVG (std::ostream& out,
                 const PersistenceDiagram& diagram,
                 const PlotOptions& options)
{
  const IntervalsByDimension intervals = checkAndGroup (diagram, options);
  const auto range = filtrationRange (intervals, options);
  const Axis axis = makeAxis (range.first,
                              range.second,
                              BARCODE_MARGIN_LEFT,
                              options.width - BARCODE_MARGIN_RIGHT);

  std::vector<BarcodePanel> panels;
  bool any_essential = false;
  for (const auto& dimension : intervals) {
    panels.push_back (selectBars (dimension, options.max_bars_per_dimension));
    const auto& bars = panels.back().bars;
    any_essential = any_essential ||
                    std::any_of (bars.begin(), bars.end(), [] (const auto& interval) {
                      return interval.isEssential();
                    });
  }
  double y = titleHeight (options.title) + (any_essential ? LEGEND_HEIGHT : 0);
  for (auto& panel : panels) {
    panel.top = y + PANEL_LABEL_HEIGHT;
    if (panel.bars.empty())
      panel.height = EMPTY_PANEL_HEIGHT;
    else {
      panel.pitch = std::min (std::max (BAR_AREA_HEIGHT / panel.bars.size(), MIN_PITCH),
                              MAX_PITCH);
      panel.height = 2 * PANEL_PADDING;
      for (const auto& bar : panel.bars)
        panel.height += rowPitch (bar, panel.pitch);
    }
    y = panel.top + panel.height + (panel.total > panel.bars.size() ? NOTE_HEIGHT : 0) +
        PANEL_GAP;
  }
  const double axis_y = y - PANEL_GAP + 6;

  writeHeader (out, options.width, axis_y + 46, options.title);
  if (any_essential) {
    const double legend_y = titleHeight (options.title) + 8;
    out << "<g class=\"essential-marker\" fill=\"" << ESSENTIAL_COLOUR << "\">\n";
    writeEssentialMarker (out, axis.px_lo, legend_y, 5);
    out << "</g>\n";
    writeText (
        out, axis.px_lo + 14, legend_y + 4, "essential class (infinite death)", "note");
  }
  for (std::size_t dimension = 0; dimension < panels.size(); ++dimension)
    writeBarcodePanel (out, panels[dimension], dimension, axis);
  if (!std::isnan (options.cut))
    writeCut (out, axis, options, panels.front().top, axis_y);
  writeAxis (out, axis, true, axis_y, withUnit ("filtration value", options.unit));
  out << "</svg>\n";
}

void
saveBarcodeSVG (const std::string& path,
                const PersistenceDiagram& diagram,
                const PlotOptions& options)
{
  writeFileAtomically (
      path, [&] (std::ostream& out) { writeBarcodeSVG (out, diagram, options); });
}

void
writePersistenceDiagramSVG (std::ostream& out,
                            const PersistenceDiagram& diagram,
                            const PlotOptions& options)
{
  const IntervalsByDimension intervals = checkAndGroup (diagram, options);
  const auto range = filtrationRange (intervals, options);
  const double left = DIAGRAM_MARGIN_LEFT;
  const double side = options.width - DIAGRAM_MARGIN_LEFT - DIAGRAM_MARGIN_RIGHT;
  const double right = left + side;
  const double infinity_y = titleHeight (options.title) + 8;
  const double top = infinity_y + INFINITY_GAP, bottom = top + side;
  const Axis x_axis = makeAxis (range.first, range.second, left, right);
  const Axis y_axis = makeAxis (range.first, range.second, bottom, top);

  std::vector<std::vector<Marker>> points (intervals.size());
  std::size_t point_count = 0;
  bool any_essential = false;
  for (std::size_t dimension = 0; dimension < intervals.size(); ++dimension)
    for (const auto& interval : intervals[dimension]) {
      any_essential = any_essential || interval.isEssential();
      points[dimension].push_back (
          {x_axis.toPixel (interval.birth),
           interval.isEssential() ? infinity_y : y_axis.toPixel (interval.death),
           1});
      ++point_count;
    }
  // One cell size for all dimensions, so that the note is exact. A coarser grid never
  // has more occupied cells, so the second round never grows the cell again.
  std::vector<std::vector<Marker>> markers;
  std::size_t marker_count = 0;
  double cell = 1;
  for (double used = 0; used != cell;) {
    used = cell;
    markers.clear();
    marker_count = 0;
    for (const auto& dimension_points : points) {
      markers.push_back (mergePoints (dimension_points, cell));
      marker_count += markers.back().size();
    }
  }
  const bool merged = marker_count < point_count;

  writeHeader (out, options.width, bottom + (merged ? 66 : 48), options.title);
  writeRect (out, left, top, side, side, "panel");
  out << "<path class=\"below-diagonal\" d=\"M" << px (left) << " " << px (bottom)
      << "H" << px (right) << "V" << px (top) << "z\"/>\n";
  writeGrid (out, x_axis, true, top, bottom);
  writeGrid (out, y_axis, false, left, right);
  writeLine (out, left, bottom, right, top, "diagonal");
  writeLine (out, left, infinity_y, right, infinity_y, "infinity");
  writeText (out, left - 8, infinity_y + 5, "\u221e", "infinity-label", "end");
  writeAxis (out, x_axis, true, bottom, withUnit ("birth", options.unit));
  writeAxis (out, y_axis, false, left, withUnit ("death", options.unit));
  if (point_count == 0)
    writeText (out, left + side / 3, top + side / 3, "no intervals", "note", "middle");

  for (std::size_t dimension = 0; dimension < markers.size(); ++dimension) {
    if (markers[dimension].empty())
      continue;
    openDimensionGroup (out, "points-H" + std::to_string (dimension), dimension);
    for (std::size_t level = 0; level < MARKER_OPACITIES.size(); ++level) {
      std::ostringstream group;
      for (const auto& marker : markers[dimension])
        if (opacityLevel (marker.count) == level)
          writeDimensionMarker (group, dimension, marker.x, marker.y);
      if (group.tellp() > 0)
        out << "<g fill-opacity=\"" << MARKER_OPACITIES[level] << "\">\n"
            << group.str() << "</g>\n";
    }
    out << "</g>\n";
  }

  // Legend in the bottom right corner, below the diagonal where no point can be.
  std::size_t rows = any_essential ? 1 : 0;
  for (const auto& dimension : intervals)
    rows += dimension.empty() ? 0 : 1;
  if (rows > 0) {
    const double legend_x = right - DIAGRAM_LEGEND_WIDTH - 8;
    double row_y = bottom - 8 - rows * DIAGRAM_LEGEND_ROW;
    writeRect (out,
               legend_x,
               row_y - 6,
               DIAGRAM_LEGEND_WIDTH,
               rows * DIAGRAM_LEGEND_ROW + 6,
               "legend");
    for (std::size_t dimension = 0; dimension < intervals.size(); ++dimension) {
      if (intervals[dimension].empty())
        continue;
      openDimensionGroup (out, "legend-H" + std::to_string (dimension), dimension);
      writeDimensionMarker (out, dimension, legend_x + 14, row_y + 6);
      out << "</g>\n";
      writeText (out,
                 legend_x + 26,
                 row_y + 10,
                 "H" + std::to_string (dimension) + " (" +
                     formatCount (intervals[dimension].size(), "point") + ")",
                 "axis-title");
      row_y += DIAGRAM_LEGEND_ROW;
    }
    if (any_essential) {
      writeLine (out, legend_x + 6, row_y + 6, legend_x + 22, row_y + 6, "infinity");
      writeText (
          out, legend_x + 26, row_y + 10, "essential (infinite death)", "axis-title");
    }
  }
  if (merged)
    writeText (
        out,
        left,
        bottom + 58,
        "Points in the same " +
            (cell == 1 ? std::string ("pixel") : formatFixed (cell, 0) + " px square") +
            " are drawn once: " + formatCount (point_count, "point") + " shown by " +
            formatCount (marker_count, "marker") + ", darker for more points.",
        "note");
  out << "</svg>\n";
}

void
savePersistenceDiagramSVG (const std::string& path,
                           const PersistenceDiagram& diagram,
                           const PlotOptions& options)
{
  writeFileAtomically (path, [&] (std::ostream& out) {
    writePersistenceDiagramSVG (out, diagram, options);
  });
}

} // namespace tda
} // namespace pcl
