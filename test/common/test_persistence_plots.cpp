#include <pcl/tda/common/persistence_plots.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using pcl::tda::PersistenceDiagram;
using pcl::tda::PersistenceInterval;
using pcl::tda::PlotOptions;

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

// A small XML reader: enough to check that the pictures are well-formed and to
// query their elements. Throws std::runtime_error on anything malformed.

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text; ///< Character data directly inside, entities decoded.
  std::vector<Element> children;
};

class XmlReader {
public:
  explicit XmlReader (const std::string& xml) : xml_ (xml) {}

  Element
  document ()
  {
    skipSpace();
    if (startsWith ("<?"))
      skipPast ("?>");
    skipSpace();
    Element root = element();
    skipSpace();
    if (pos_ != xml_.size())
      fail ("content after the root element");
    return root;
  }

private:
  [[noreturn]] void
  fail (const std::string& what) const
  {
    throw std::runtime_error ("malformed XML: " + what + " at offset " +
                              std::to_string (pos_));
  }

  bool
  startsWith (const char* prefix) const
  {
    return xml_.compare (pos_, std::char_traits<char>::length (prefix), prefix) == 0;
  }

  void
  skipPast (const char* end)
  {
    const auto at = xml_.find (end, pos_);
    if (at == std::string::npos)
      fail (std::string ("missing ") + end);
    pos_ = at + std::char_traits<char>::length (end);
  }

  void
  skipSpace ()
  {
    while (pos_ < xml_.size() && std::isspace (static_cast<unsigned char> (xml_[pos_])))
      ++pos_;
  }

  void
  expect (char c)
  {
    if (pos_ >= xml_.size() || xml_[pos_] != c)
      fail (std::string ("expected '") + c + "'");
    ++pos_;
  }

  std::string
  name ()
  {
    const auto start = pos_;
    while (pos_ < xml_.size() &&
           (std::isalnum (static_cast<unsigned char> (xml_[pos_])) ||
            std::string ("_:.-").find (xml_[pos_]) != std::string::npos))
      ++pos_;
    if (pos_ == start)
      fail ("expected a name");
    return xml_.substr (start, pos_ - start);
  }

  /** Decodes the entity at pos_ (which is '&'). */
  std::string
  entity ()
  {
    const auto end = xml_.find (';', pos_);
    if (end == std::string::npos)
      fail ("unterminated entity");
    const std::string entity_name = xml_.substr (pos_ + 1, end - pos_ - 1);
    const std::map<std::string, std::string> known = {
        {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
    const auto found = known.find (entity_name);
    if (found == known.end())
      fail ("unknown entity &" + entity_name + ";");
    pos_ = end + 1;
    return found->second;
  }

  Element
  element ()
  {
    expect ('<');
    Element result;
    result.name = name();
    for (;;) {
      skipSpace();
      if (startsWith ("/>")) {
        pos_ += 2;
        return result;
      }
      if (startsWith (">")) {
        ++pos_;
        break;
      }
      const std::string attribute = name();
      skipSpace();
      expect ('=');
      skipSpace();
      if (pos_ >= xml_.size() || (xml_[pos_] != '"' && xml_[pos_] != '\''))
        fail ("expected a quoted attribute value");
      const char quote = xml_[pos_++];
      std::string value;
      while (pos_ < xml_.size() && xml_[pos_] != quote) {
        if (xml_[pos_] == '<')
          fail ("'<' in an attribute value");
        if (xml_[pos_] == '&')
          value += entity();
        else
          value += xml_[pos_++];
      }
      expect (quote);
      if (!result.attributes.emplace (attribute, value).second)
        fail ("repeated attribute " + attribute);
    }
    for (;;) {
      if (pos_ >= xml_.size())
        fail ("unclosed <" + result.name + ">");
      if (startsWith ("</")) {
        pos_ += 2;
        if (name() != result.name)
          fail ("mismatched closing tag for <" + result.name + ">");
        skipSpace();
        expect ('>');
        return result;
      }
      if (startsWith ("<!--"))
        skipPast ("-->");
      else if (xml_[pos_] == '<')
        result.children.push_back (element());
      else if (xml_[pos_] == '&')
        result.text += entity();
      else if (xml_[pos_] == '>')
        fail ("raw '>' in text");
      else
        result.text += xml_[pos_++];
    }
  }

  const std::string& xml_;
  std::size_t pos_ = 0;
};

Element
parseXml (const std::string& xml)
{
  return XmlReader (xml).document();
}

bool
hasClass (const Element& element, const std::string& cls)
{
  const auto found = element.attributes.find ("class");
  if (found == element.attributes.end())
    return false;
  std::istringstream classes (found->second);
  std::string word;
  while (classes >> word)
    if (word == cls)
      return true;
  return false;
}

void
collect (const Element& element,
         const std::function<bool (const Element&)>& wanted,
         std::vector<const Element*>& found)
{
  if (wanted (element))
    found.push_back (&element);
  for (const auto& child : element.children)
    collect (child, wanted, found);
}

/** All elements under \a root (itself included) that satisfy \a wanted, in document
 * order. */
std::vector<const Element*>
findAll (const Element& root, const std::function<bool (const Element&)>& wanted)
{
  std::vector<const Element*> found;
  collect (root, wanted, found);
  return found;
}

std::vector<const Element*>
withClass (const Element& root, const std::string& cls)
{
  return findAll (root, [&] (const Element& e) { return hasClass (e, cls); });
}

const Element&
withId (const Element& root, const std::string& id)
{
  const auto found = findAll (root, [&] (const Element& e) {
    const auto attribute = e.attributes.find ("id");
    return attribute != e.attributes.end() && attribute->second == id;
  });
  if (found.size() != 1)
    throw std::runtime_error ("expected one element with id " + id);
  return *found.front();
}

/** Shapes (rect, circle, path) under \a root. */
std::vector<const Element*>
shapes (const Element& root)
{
  return findAll (root, [] (const Element& e) {
    return e.name == "rect" || e.name == "circle" || e.name == "path";
  });
}

std::vector<std::string>
texts (const std::vector<const Element*>& elements)
{
  std::vector<std::string> result;
  for (const auto* element : elements)
    result.push_back (element->text);
  return result;
}

bool
containsText (const Element& root, const std::string& text)
{
  return !findAll (root, [&] (const Element& e) {
            return e.text.find (text) != std::string::npos;
          }).empty();
}

double
number (const Element& element, const std::string& attribute)
{
  return std::stod (element.attributes.at (attribute));
}

std::string
barcode (const PersistenceDiagram& diagram, const PlotOptions& options = {})
{
  std::ostringstream out;
  pcl::tda::writeBarcodeSVG (out, diagram, options);
  return out.str();
}

std::string
persistenceDiagram (const PersistenceDiagram& diagram, const PlotOptions& options = {})
{
  std::ostringstream out;
  pcl::tda::writePersistenceDiagramSVG (out, diagram, options);
  return out.str();
}

/** Six intervals of non-zero length (two essential) and two of zero length. */
PersistenceDiagram
smallDiagram ()
{
  return {{0, 0, 0.1},
          {0, 0, 0.2},
          {0, 0, INF},
          {0, 0.05, 0.05},
          {1, 0.1, 0.3},
          {1, 0.12, 0.15},
          {1, 0.2, INF},
          {1, 0.25, 0.25}};
}

/** 100,001 intervals: H0 has 50,000 finite ones and 1 essential, H1 49,997 finite
 * and 3 essential. */
PersistenceDiagram
hugeDiagram ()
{
  std::mt19937 random (42);
  std::uniform_real_distribution<double> death (0.0001, 0.05);
  std::uniform_real_distribution<double> birth (0.01, 0.04);
  std::exponential_distribution<double> life (500.0);
  PersistenceDiagram diagram;
  for (int i = 0; i < 50000; ++i)
    diagram.push_back ({0, 0, death (random)});
  diagram.push_back ({0, 0, INF});
  for (int i = 0; i < 49997; ++i) {
    const double b = birth (random);
    diagram.push_back ({1, b, b + 1e-6 + life (random)});
  }
  for (int i = 0; i < 3; ++i)
    diagram.push_back ({1, birth (random), INF});
  return diagram;
}

/** Length of the longest finite interval of \a dimension not among the \a kept
 * longest. */
double
longestHidden (const PersistenceDiagram& diagram, int dimension, std::size_t kept)
{
  std::vector<double> lengths;
  for (const auto& interval : diagram)
    if (interval.dimension == dimension)
      lengths.push_back (interval.death - interval.birth);
  std::sort (lengths.rbegin(), lengths.rend());
  return lengths.at (kept);
}

TEST (PersistencePlots, XmlReaderRejectsMalformedText)
{
  EXPECT_NO_THROW (parseXml ("<svg a=\"1\"><g>x &amp; y</g><rect/></svg>"));
  EXPECT_THROW (parseXml ("<svg><g></svg>"), std::runtime_error);
  EXPECT_THROW (parseXml ("<svg><g>"), std::runtime_error);
  EXPECT_THROW (parseXml ("<svg>a & b</svg>"), std::runtime_error);
  EXPECT_THROW (parseXml ("<svg a=\"<\"/>"), std::runtime_error);
  EXPECT_THROW (parseXml ("<svg/><svg/>"), std::runtime_error);
}

TEST (BarcodeSVG, DrawsOneBarPerNonZeroInterval)
{
  const Element svg = parseXml (barcode (smallDiagram()));
  EXPECT_EQ (svg.name, "svg");
  EXPECT_EQ (withClass (svg, "bar").size(), 6u);
  EXPECT_EQ (withClass (svg, "essential").size(), 2u);
  EXPECT_EQ (shapes (withId (svg, "barcode-H0")).size(), 3u);
  EXPECT_EQ (shapes (withId (svg, "barcode-H1")).size(), 3u);
  EXPECT_EQ (texts (withClass (svg, "panel-label")),
             (std::vector<std::string>{"H0 (3 intervals)", "H1 (3 intervals)"}));
  // One red triangle per essential bar and one in the legend that explains them.
  std::size_t triangles = 0;
  for (const auto* group : withClass (svg, "essential-marker"))
    triangles += shapes (*group).size();
  EXPECT_EQ (triangles, 3u);
  EXPECT_TRUE (containsText (svg, "essential class (infinite death)"));
  EXPECT_TRUE (withClass (svg, "note").size() == 1); // the legend, no hidden bars
}

TEST (BarcodeSVG, BarsSpanTheirIntervalsSortedByBirthThenLength)
{
  const Element svg = parseXml (barcode (smallDiagram()));
  const auto panels = withClass (svg, "panel");
  ASSERT_EQ (panels.size(), 2u);
  const double left = number (*panels[0], "x");
  const double right = left + number (*panels[0], "width");
  // The axis ends at the largest finite value, 0.3.
  const auto pixel = [&] (double value) { return left + (right - left) * value / 0.3; };
  const std::vector<std::pair<double, double>> expected = {
      {0, INF}, {0, 0.2}, {0, 0.1}, {0.1, 0.3}, {0.12, 0.15}, {0.2, INF}};
  const auto bars = withClass (svg, "bar");
  ASSERT_EQ (bars.size(), expected.size());
  for (std::size_t i = 0; i < bars.size(); ++i) {
    SCOPED_TRACE (i);
    const double start = number (*bars[i], "x");
    const double end = start + number (*bars[i], "width");
    EXPECT_NEAR (start, pixel (expected[i].first), 0.11);
    if (std::isinf (expected[i].second)) {
      EXPECT_TRUE (hasClass (*bars[i], "essential"));
      EXPECT_NEAR (end, right, 0.11);
    }
    else {
      EXPECT_NEAR (end, pixel (expected[i].second), 0.11);
    }
    if (i % 3 != 0) { // top to bottom within a panel
      EXPECT_GT (number (*bars[i], "y"), number (*bars[i - 1], "y"));
    }
  }
}

TEST (BarcodeSVG, TickLabelsAreRoundValues)
{
  const auto labels = [] (const PersistenceDiagram& diagram, double max_value) {
    PlotOptions options;
    options.max_value = max_value;
    return texts (withClass (parseXml (barcode (diagram, options)), "tick-label"));
  };
  using Labels = std::vector<std::string>;
  EXPECT_EQ (labels (smallDiagram(), 0.037), (Labels{"0", "0.01", "0.02", "0.03"}));
  EXPECT_EQ (labels ({{0, 0, 2.5}}, 0), (Labels{"0", "0.5", "1", "1.5", "2", "2.5"}));
  EXPECT_EQ (labels ({{0, 0, 7}}, 0), (Labels{"0", "2", "4", "6"}));
  EXPECT_EQ (labels ({{0, 0, 1}}, 1500), (Labels{"0", "500", "1000", "1500"}));
  EXPECT_EQ (labels ({{0, 0, 0.3}}, 0),
             (Labels{"0", "0.05", "0.1", "0.15", "0.2", "0.25", "0.3"}));
  EXPECT_EQ (labels ({{0, -0.2, 0.1}}, 0),
             (Labels{"-0.2", "-0.15", "-0.1", "-0.05", "0", "0.05", "0.1"}));

  // The labels sit where their values are on the axis.
  PlotOptions options;
  options.max_value = 0.037;
  const Element svg = parseXml (barcode (smallDiagram(), options));
  const auto& panel = *withClass (svg, "panel").front();
  const double left = number (panel, "x"), width = number (panel, "width");
  const auto ticks = withClass (svg, "tick-label");
  for (std::size_t i = 0; i < ticks.size(); ++i)
    EXPECT_NEAR (number (*ticks[i], "x"), left + width * 0.01 * i / 0.037, 0.11);
}

TEST (BarcodeSVG, CapsHugeDiagramsAndCountsTheHiddenBars)
{
  const PersistenceDiagram diagram = hugeDiagram();
  const std::string text = barcode (diagram);
  EXPECT_LT (text.size(), 200000u);
  const Element svg = parseXml (text);
  const auto h0 = shapes (withId (svg, "barcode-H0"));
  const auto h1 = shapes (withId (svg, "barcode-H1"));
  EXPECT_EQ (h0.size(), 200u);
  EXPECT_EQ (h1.size(), 200u);
  EXPECT_EQ (
      texts (withClass (svg, "panel-label")),
      (std::vector<std::string>{"H0 (50,001 intervals)", "H1 (50,000 intervals)"}));
  // All essential bars are drawn.
  EXPECT_EQ (shapes (*withClass (svg, "essential-marker")[1]).size(), 1u);
  EXPECT_EQ (shapes (*withClass (svg, "essential-marker")[2]).size(), 3u);

  const auto notes = texts (withClass (svg, "note"));
  const std::vector<std::string> prefixes = {"+ 49,801 shorter bars (length \u2264 ",
                                             "+ 49,800 shorter bars (length \u2264 "};
  const auto& panel = *withClass (svg, "panel").front();
  double largest_death = 0;
  for (const auto& interval : diagram)
    if (!interval.isEssential())
      largest_death = std::max (largest_death, interval.death);
  const double pixels_per_unit = number (panel, "width") / largest_death;
  for (int dimension = 0; dimension < 2; ++dimension) {
    SCOPED_TRACE (dimension);
    const auto note = std::find_if (notes.begin(), notes.end(), [&] (const auto& n) {
      return n.rfind (prefixes[dimension], 0) == 0;
    });
    ASSERT_NE (note, notes.end());
    EXPECT_EQ (note->substr (note->size() - 11), ") not drawn");
    const double bound = std::stod (note->substr (prefixes[dimension].size()));
    const double hidden = longestHidden (diagram, dimension, 200);
    EXPECT_GE (bound, hidden);
    EXPECT_LE (bound, 1.1 * hidden);
    // The drawn bars are the longest ones.
    for (const auto* bar : dimension == 0 ? h0 : h1)
      EXPECT_GE (number (*bar, "width"), hidden * pixels_per_unit - 0.11);
  }

  PlotOptions options;
  options.max_bars_per_dimension = 50;
  options.max_value = 0.05;
  const Element fewer = parseXml (barcode (diagram, options));
  EXPECT_EQ (shapes (withId (fewer, "barcode-H0")).size(), 50u);
  EXPECT_EQ (shapes (withId (fewer, "barcode-H1")).size(), 50u);
  EXPECT_TRUE (containsText (fewer, "+ 49,951 shorter bars"));
}

TEST (BarcodeSVG, KeepsEarliestEssentialBarsWhenTheyExceedTheCap)
{
  PersistenceDiagram diagram;
  for (int i = 0; i < 300; ++i)
    diagram.push_back ({0, 0.001 * i, INF});
  for (int i = 0; i < 1000; ++i)
    diagram.push_back ({0, 0, 0.5});
  PlotOptions options;
  options.max_bars_per_dimension = 100;
  const Element svg = parseXml (barcode (diagram, options));
  const auto bars = withClass (svg, "bar");
  ASSERT_EQ (bars.size(), 100u);
  for (const auto* bar : bars)
    EXPECT_TRUE (hasClass (*bar, "essential"));
  EXPECT_TRUE (containsText (svg,
                             "+ 1,200 bars not drawn: 200 essential born later, "
                             "1,000 finite"));
}

TEST (BarcodeSVG, EmptyDiagramsAndDimensionsSayNoIntervals)
{
  const Element empty = parseXml (barcode ({}));
  EXPECT_TRUE (withClass (empty, "bar").empty());
  EXPECT_EQ (texts (withClass (empty, "panel-label")),
             (std::vector<std::string>{"H0 (0 intervals)"}));
  EXPECT_TRUE (containsText (empty, "no intervals"));
  EXPECT_FALSE (withClass (empty, "tick-label").empty());

  const Element gap = parseXml (barcode ({{0, 0, 1}, {2, 0.1, 0.5}, {1, 0.3, 0.3}}));
  EXPECT_EQ (texts (withClass (gap, "panel-label")),
             (std::vector<std::string>{
                 "H0 (1 interval)", "H1 (0 intervals)", "H2 (1 interval)"}));
  EXPECT_EQ (withClass (gap, "bar").size(), 2u);
  const auto notes = texts (withClass (gap, "note"));
  EXPECT_EQ (std::count (notes.begin(), notes.end(), "no intervals"), 1);
}

TEST (BarcodeSVG, EscapesTheTitle)
{
  PlotOptions options;
  options.title = "Scene <1> & \"chair's\"";
  const std::string text = barcode (smallDiagram(), options);
  EXPECT_EQ (text.find ("<1>"), std::string::npos);
  const Element svg = parseXml (text);
  EXPECT_EQ (texts (withClass (svg, "title")), std::vector<std::string>{options.title});
  const auto titles =
      findAll (svg, [] (const Element& e) { return e.name == "title"; });
  ASSERT_FALSE (titles.empty());
  EXPECT_EQ (titles.front()->text, options.title);

  const Element diagram = parseXml (persistenceDiagram (smallDiagram(), options));
  EXPECT_EQ (texts (withClass (diagram, "title")),
             std::vector<std::string>{options.title});
}

TEST (BarcodeSVG, RejectsInvalidInput)
{
  using pcl::BadArgumentException;
  EXPECT_THROW (barcode ({{0, 0.5, 0.4}}), BadArgumentException);
  EXPECT_THROW (barcode ({{0, std::nan (""), 1}}), BadArgumentException);
  EXPECT_THROW (barcode ({{0, -INF, 1}}), BadArgumentException);
  EXPECT_THROW (barcode ({{-1, 0, 1}}), BadArgumentException);
  EXPECT_THROW (persistenceDiagram ({{0, 0, std::nan ("")}}), BadArgumentException);
  PlotOptions options;
  options.max_bars_per_dimension = 0;
  EXPECT_THROW (barcode (smallDiagram(), options), BadArgumentException);
  options = {};
  options.max_value = -1;
  EXPECT_THROW (barcode (smallDiagram(), options), BadArgumentException);
  options = {};
  options.width = 10;
  EXPECT_THROW (persistenceDiagram (smallDiagram(), options), BadArgumentException);
  for (const double cut : {-0.1, INF}) {
    options = {};
    options.cut = cut;
    EXPECT_THROW (barcode (smallDiagram(), options), BadArgumentException) << cut;
  }
}

TEST (BarcodeSVG, SeveralEssentialBarsStaySeparate)
{
  // Four clusters among 500 finite bars: the finite bars are 2 pixels apart, the
  // essential ones MIN_ESSENTIAL_PITCH, with a gap of 2 pixels between them.
  PersistenceDiagram diagram;
  for (int i = 0; i < 4; ++i)
    diagram.push_back ({0, 0, INF});
  for (int i = 1; i <= 500; ++i)
    diagram.push_back ({0, 0, 0.001 * i});
  const auto svg = parseXml (barcode (diagram)); // the bars point into it
  const auto bars = withClass (svg, "essential");
  ASSERT_EQ (bars.size(), 4u);
  for (std::size_t i = 1; i < bars.size(); ++i) {
    const double top = number (*bars[i], "y");
    const double previous_bottom =
        number (*bars[i - 1], "y") + number (*bars[i - 1], "height");
    EXPECT_NEAR (top - number (*bars[i - 1], "y"), pcl::tda::MIN_ESSENTIAL_PITCH, 0.11);
    EXPECT_GE (top - previous_bottom, 1.9);
  }
}

TEST (BarcodeSVG, DrawsTheCutLineAndTheUnit)
{
  PlotOptions options;
  options.max_value = 0.4;
  options.cut = 0.0123;
  options.unit = "m";
  const Element svg = parseXml (barcode (smallDiagram(), options));
  const auto cuts = withClass (svg, "cut");
  ASSERT_EQ (cuts.size(), 1u);
  const auto panels = withClass (svg, "panel");
  const double left = number (*panels[0], "x");
  const double right = left + number (*panels[0], "width");
  EXPECT_NEAR (number (*cuts[0], "x1"), left + (right - left) * 0.0123 / 0.4, 0.11);
  EXPECT_EQ (number (*cuts[0], "x1"), number (*cuts[0], "x2"));
  // From the top of the first panel down to the axis, past the last panel.
  EXPECT_LE (number (*cuts[0], "y1"), number (*panels[0], "y"));
  EXPECT_GE (number (*cuts[0], "y2"),
             number (*panels[1], "y") + number (*panels[1], "height"));
  EXPECT_EQ (texts (withClass (svg, "cut-label")),
             (std::vector<std::string>{"cut 0.0123 m"}));
  EXPECT_EQ (texts (withClass (svg, "axis-title")),
             (std::vector<std::string>{"filtration value (m)"}));

  // A cut beyond the data extends the axis; without a unit, none is named.
  options = {};
  options.cut = 0.5;
  const Element beyond = parseXml (barcode (smallDiagram(), options));
  EXPECT_EQ (texts (withClass (beyond, "cut-label")),
             (std::vector<std::string>{"cut 0.5"}));
  EXPECT_EQ (texts (withClass (beyond, "axis-title")),
             (std::vector<std::string>{"filtration value"}));
  EXPECT_EQ (texts (withClass (beyond, "tick-label")).back(), "0.5");

  // No cut by default; the persistence diagram names the unit on both axes.
  EXPECT_TRUE (withClass (parseXml (barcode (smallDiagram())), "cut").empty());
  options = {};
  options.unit = "mm";
  const Element diagram = parseXml (persistenceDiagram (smallDiagram(), options));
  EXPECT_TRUE (containsText (diagram, "birth (mm)"));
  EXPECT_TRUE (containsText (diagram, "death (mm)"));
}

TEST (PersistencePlots, SaveWritesTheFileOrThrows)
{
  const std::string path =
      (std::filesystem::path (::testing::TempDir()) /
       ("test_persistence_plots_" + std::to_string (::getpid()) + ".svg"))
          .string();
  const auto read = [&] {
    std::ifstream in (path);
    return std::string (std::istreambuf_iterator<char> (in), {});
  };
  pcl::tda::saveBarcodeSVG (path, smallDiagram());
  EXPECT_EQ (read(), barcode (smallDiagram()));
  pcl::tda::savePersistenceDiagramSVG (path, smallDiagram());
  EXPECT_EQ (read(), persistenceDiagram (smallDiagram()));
  std::filesystem::remove (path);

  const std::string unwritable = "/nonexistent-directory-of-pcl-tda/plot.svg";
  EXPECT_THROW (pcl::tda::saveBarcodeSVG (unwritable, smallDiagram()),
                pcl::IOException);
  EXPECT_THROW (pcl::tda::savePersistenceDiagramSVG (unwritable, smallDiagram()),
                pcl::IOException);
}

TEST (PersistenceDiagramSVG, DrawsOneMarkerPerPointAndEssentialOnTheInfinityLine)
{
  const Element svg = parseXml (persistenceDiagram (smallDiagram()));
  const auto h0 = shapes (withId (svg, "points-H0"));
  const auto h1 = shapes (withId (svg, "points-H1"));
  ASSERT_EQ (h0.size(), 3u);
  ASSERT_EQ (h1.size(), 3u);
  EXPECT_EQ (withClass (svg, "diagonal").size(), 1u);

  const auto& panel = *withClass (svg, "panel").front();
  const double left = number (panel, "x"), top = number (panel, "y");
  const double side = number (panel, "width");
  const double infinity = number (*withClass (svg, "infinity").front(), "y1");
  EXPECT_LT (infinity, top);
  // H0 circles sorted from top to bottom: (0, inf), (0, 0.2), (0, 0.1).
  const std::vector<double> deaths = {INF, 0.2, 0.1};
  for (std::size_t i = 0; i < h0.size(); ++i) {
    SCOPED_TRACE (i);
    EXPECT_EQ (h0[i]->name, "circle");
    EXPECT_NEAR (number (*h0[i], "cx"), left, 0.11);
    const double expected_y =
        std::isinf (deaths[i]) ? infinity : top + side - side * deaths[i] / 0.3;
    EXPECT_NEAR (number (*h0[i], "cy"), expected_y, 0.11);
  }

  const auto ticks = texts (withClass (svg, "tick-label"));
  for (const char* label : {"0", "0.05", "0.1", "0.15", "0.2", "0.25", "0.3"})
    EXPECT_EQ (std::count (ticks.begin(), ticks.end(), label), 2) << label; // x and y
  EXPECT_EQ (texts (withClass (svg, "infinity-label")),
             std::vector<std::string>{"\u221e"});
  EXPECT_TRUE (containsText (svg, "H0 (3 points)"));
  EXPECT_TRUE (containsText (svg, "essential (infinite death)"));
  EXPECT_TRUE (withClass (svg, "note").empty()); // nothing merged
}

TEST (PersistenceDiagramSVG, MergesPointsOnTheSamePixel)
{
  PersistenceDiagram diagram (10, {1, 0.2, 0.7});
  diagram.push_back ({1, 0.1, 0.9});
  const Element svg = parseXml (persistenceDiagram (diagram));
  EXPECT_EQ (shapes (withId (svg, "points-H1")).size(), 2u);
  EXPECT_EQ (
      texts (withClass (svg, "note")),
      std::vector<std::string>{"Points in the same pixel are drawn once: 11 points "
                               "shown by 2 markers, darker for more points."});
}

TEST (PersistenceDiagramSVG, StaysSmallForHugeDiagrams)
{
  const std::string text = persistenceDiagram (hugeDiagram());
  EXPECT_LT (text.size(), 200000u);
  const Element svg = parseXml (text);
  EXPECT_LE (shapes (withId (svg, "points-H0")).size(), 1000u);
  EXPECT_LE (shapes (withId (svg, "points-H1")).size(), 1000u);
  EXPECT_TRUE (containsText (svg, "H1 (50,000 points)"));
  const auto notes = texts (withClass (svg, "note"));
  ASSERT_EQ (notes.size(), 1u);
  EXPECT_NE (notes.front().find ("100,001 points shown by"), std::string::npos);
}

TEST (PersistenceDiagramSVG, EmptyDiagramSaysNoIntervals)
{
  const Element svg = parseXml (persistenceDiagram ({}));
  EXPECT_TRUE (containsText (svg, "no intervals"));
  EXPECT_TRUE (shapes (svg).size() >= 1u); // background and frame only
  EXPECT_TRUE (
      findAll (svg, [] (const Element& e) { return e.name == "circle"; }).empty());
}

} // namespace
