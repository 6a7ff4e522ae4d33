#include <pcl/tda/apps/confusion_matrix_plot.h>
#include <pcl/tda/apps/rgb_image.h>
#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

namespace pcl {
namespace tda {
namespace {

/** The label of the column of views that got no category. */
constexpr const char* NO_CATEGORY = "(failed)";
constexpr const char* ROWS_TITLE = "true category";
constexpr const char* COLUMNS_TITLE = "predicted category";

/** The rows and columns to draw, their labels and shares. */
struct Matrix {
  std::vector<std::string> row_labels, column_labels;
  /** share[t][p]: counts[t][p] over the row's total (0 for an empty row). */
  std::vector<std::vector<double>> share;
};

Matrix
matrixOf (const ConfusionPlot& plot)
{
  const std::size_t n = plot.categories.size();
  if (plot.counts.size() != n)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "A confusion matrix needs a row per category.");
  bool failures = false;
  for (const auto& row : plot.counts) {
    if (row.size() != n + 1)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "A confusion matrix row needs a column per category and "
                           "one for no category.");
    failures = failures || row[n] > 0;
  }
  Matrix matrix;
  matrix.column_labels = plot.categories;
  if (failures)
    matrix.column_labels.push_back (NO_CATEGORY);
  for (std::size_t t = 0; t < n; ++t) {
    std::size_t total = 0;
    for (const std::size_t count : plot.counts[t])
      total += count;
    matrix.row_labels.push_back (plot.categories[t] + " (" + std::to_string (total) +
                                 ")");
    std::vector<double> shares;
    for (std::size_t p = 0; p < matrix.column_labels.size(); ++p)
      shares.push_back (total == 0 ? 0.0
                                   : static_cast<double> (plot.counts[t][p]) /
                                         static_cast<double> (total));
    matrix.share.push_back (shares);
  }
  return matrix;
}

/** "0.93": a share with two decimals. */
std::string
shareText (double share)
{
  char text[16];
  std::snprintf (text, sizeof (text), "%.2f", share);
  return text;
}

/** The colour of a cell of share \a share: white to dark blue. */
RGB
shade (double share)
{
  constexpr RGB LOW{255, 255, 255}, HIGH{8, 48, 107};
  RGB color;
  for (int k = 0; k < 3; ++k)
    color[k] = static_cast<std::uint8_t> (
        std::lround (LOW[k] + (HIGH[k] - LOW[k]) * std::clamp (share, 0.0, 1.0)));
  return color;
}

/** The colour of the text on a cell of share \a share. */
RGB
ink (double share)
{
  return share > 0.5 ? RGB{255, 255, 255} : RGB{0, 0, 0};
}

/** The SVG's text: 12 px monospace, characters about 7.2 px wide, lines 15 px. */
constexpr double CHAR_WIDTH = 7.2, LINE_HEIGHT = 15;

/** Where things go, in pixels, under a title of \a title_characters characters. */
struct Layout {
  double cell, left, top, width, height, line;
};

std::size_t
longest (const std::vector<std::string>& labels)
{
  std::size_t most = 0;
  for (const std::string& label : labels)
    most = std::max (most, label.size());
  return most;
}

Layout
layoutOf (const Matrix& matrix, std::size_t title_characters)
{
  constexpr double MARGIN = 12;
  Layout layout;
  layout.line = LINE_HEIGHT;
  layout.cell = std::max (56.0, CHAR_WIDTH * 4 + 16);
  // Title, the columns' title, then the column labels turned upright.
  layout.top = MARGIN + 3 * LINE_HEIGHT +
               CHAR_WIDTH * static_cast<double> (longest (matrix.column_labels)) + 8;
  // The rows' title turned upright, then the row labels.
  layout.left = MARGIN + LINE_HEIGHT + 8 +
                CHAR_WIDTH * static_cast<double> (longest (matrix.row_labels)) + 8;
  const double columns = static_cast<double> (matrix.column_labels.size());
  const double rows = static_cast<double> (matrix.row_labels.size());
  layout.width =
      std::max (layout.left + layout.cell * columns + MARGIN,
                2 * MARGIN + CHAR_WIDTH * static_cast<double> (title_characters));
  layout.height = layout.top + layout.cell * rows + MARGIN;
  return layout;
}

std::string
escapeXML (const std::string& text)
{
  static const std::pair<char, const char*> ENTITIES[] = {
      {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}, {'\'', "&apos;"}};
  std::string escaped;
  for (const char c : text) {
    const auto* entity = std::find_if (std::begin (ENTITIES),
                                       std::end (ENTITIES),
                                       [c] (const auto& e) { return e.first == c; });
    if (entity != std::end (ENTITIES))
      escaped += entity->second;
    else if (static_cast<unsigned char> (c) >= 0x20) // no control characters in XML
      escaped += c;
  }
  return escaped;
}

std::string
hex (const RGB& color)
{
  char text[8];
  std::snprintf (text, sizeof (text), "#%02x%02x%02x", color[0], color[1], color[2]);
  return text;
}

} // namespace

void
writeConfusionMatrixSVG (std::ostream& out, const ConfusionPlot& plot)
{
  const Matrix matrix = matrixOf (plot);
  const Layout layout = layoutOf (matrix, plot.title.size());
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << layout.width
      << "\" height=\"" << layout.height << "\" font-family=\"monospace\" "
      << "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"12\" y=\"" << 12 + layout.line << "\" font-weight=\"bold\">"
      << escapeXML (plot.title) << "</text>\n";
  const double matrix_width =
      layout.cell * static_cast<double> (matrix.column_labels.size());
  const double matrix_height =
      layout.cell * static_cast<double> (matrix.row_labels.size());
  out << "<text x=\"" << layout.left + matrix_width / 2 << "\" y=\""
      << 12 + 3 * layout.line << "\" text-anchor=\"middle\">" << COLUMNS_TITLE
      << "</text>\n";
  const double rows_x = 12 + layout.line, rows_y = layout.top + matrix_height / 2;
  out << "<text x=\"" << rows_x << "\" y=\"" << rows_y << "\" transform=\"rotate(-90 "
      << rows_x << " " << rows_y << ")\" text-anchor=\"middle\">" << ROWS_TITLE
      << "</text>\n";
  for (std::size_t p = 0; p < matrix.column_labels.size(); ++p) {
    const double x = layout.left + layout.cell * (static_cast<double> (p) + 0.5) + 4;
    const double y = layout.top - 6;
    out << "<text x=\"" << x << "\" y=\"" << y << "\" transform=\"rotate(-90 " << x
        << " " << y << ")\">" << escapeXML (matrix.column_labels[p]) << "</text>\n";
  }
  for (std::size_t t = 0; t < matrix.row_labels.size(); ++t) {
    const double y = layout.top + layout.cell * static_cast<double> (t);
    out << "<text x=\"" << layout.left - 8 << "\" y=\"" << y + layout.cell / 2 + 4
        << "\" text-anchor=\"end\">" << escapeXML (matrix.row_labels[t]) << "</text>\n";
    for (std::size_t p = 0; p < matrix.column_labels.size(); ++p) {
      const double x = layout.left + layout.cell * static_cast<double> (p);
      const double share = matrix.share[t][p];
      out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << layout.cell
          << "\" height=\"" << layout.cell << "\" fill=\"" << hex (shade (share))
          << "\" stroke=\"#999\"/>\n<text x=\"" << x + layout.cell / 2 << "\" y=\""
          << y + layout.cell / 2 + 4 << "\" text-anchor=\"middle\" fill=\""
          << hex (ink (share)) << "\">" << shareText (share) << "</text>\n";
    }
  }
  out << "</svg>\n";
}

void
saveConfusionMatrixSVG (const std::string& path, const ConfusionPlot& plot)
{
  writeFileAtomically (
      path, [&plot] (std::ostream& out) { writeConfusionMatrixSVG (out, plot); });
}

void
saveConfusionMatrixPNG (const std::string& path, const ConfusionPlot& plot)
{
  // The SVG picture, rendered by librsvg from a scratch file beside the PNG.
  const std::string svg = path + ".svg";
  saveConfusionMatrixSVG (svg, plot);
  try {
    renderSVGToPNG (svg, path);
  }
  catch (...) {
    std::filesystem::remove (svg);
    throw;
  }
  std::filesystem::remove (svg);
}

} // namespace tda
} // namespace pcl
