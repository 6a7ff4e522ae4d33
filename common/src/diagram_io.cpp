#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <string_view>
#include <tuple>
#include <vector>

namespace pcl {
namespace tda {

namespace {

constexpr std::string_view CSV_HEADER = "dim,birth,death";
constexpr std::size_t CSV_COLUMNS = 3;
constexpr std::string_view RIPSER_INTERVALS = "persistence intervals in dim ";
/** Lines one of which Ripser 1.2 prints first. */
constexpr std::string_view RIPSER_FIRST_LINES[] = {"point cloud with ",
                                                   "distance matrix with ",
                                                   "sparse distance matrix with ",
                                                   "value range: ",
                                                   RIPSER_INTERVALS};
/** Longest part of an offending line quoted in an error message. */
constexpr std::size_t MAX_QUOTED = 80;

std::string_view
trim (std::string_view text)
{
  const auto first = text.find_first_not_of (" \t\r\n");
  if (first == std::string_view::npos)
    return {};
  return text.substr (first, text.find_last_not_of (" \t\r\n") - first + 1);
}

bool
startsWith (std::string_view text, std::string_view prefix)
{
  return text.substr (0, prefix.size()) == prefix;
}

std::vector<std::string_view>
splitFields (std::string_view line)
{
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (auto comma = line.find (','); comma != std::string_view::npos;
       comma = line.find (',', start)) {
    fields.push_back (trim (line.substr (start, comma - start)));
    start = comma + 1;
  }
  fields.push_back (trim (line.substr (start)));
  return fields;
}

/** Why (dimension, birth, death) is not a valid interval, or nullptr. */
const char*
intervalProblem (int dimension, double birth, double death)
{
  if (dimension < 0)
    return "negative dimension";
  if (std::isnan (birth) || std::isnan (death))
    return "NaN value";
  if (!std::isfinite (birth))
    return "infinite birth";
  if (death < birth)
    return "death smaller than birth";
  return nullptr;
}

/** Reads lines, counting them, and throws errors that name the current line. */
class LineReader {
public:
  LineReader (std::istream& in, const std::string& source) : in_ (in), source_ (source)
  {}

  /** Reads the next line that is not blank; false at the end of the input. */
  bool
  nextLine ()
  {
    while (std::getline (in_, line_)) {
      ++number_;
      text_ = trim (line_);
      if (!text_.empty())
        return true;
    }
    at_end_ = true;
    if (in_.bad())
      fail ("read error");
    return false;
  }

  /** The current line without surrounding white space. */
  std::string_view
  text () const
  {
    return text_;
  }

  /** Throws pcl::IOException naming the current line, or the end of the input. */
  [[noreturn]] void
  fail (const std::string& problem) const
  {
    const std::string where = source_.empty() ? "" : source_ + ": ";
    if (at_end_)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           where << "line " << number_ + 1
                                 << " (end of input): " << problem);
    PCL_THROW_EXCEPTION (pcl::IOException,
                         where << "line " << number_ << ": " << problem << " in \""
                               << line_.substr (0, MAX_QUOTED)
                               << (line_.size() > MAX_QUOTED ? "...\"" : "\""));
  }

  /** The finite or infinite number in \a field, called \a name in errors. */
  double
  parseValue (std::string_view field, const char* name) const
  {
    double value = 0.0;
    const auto result =
        std::from_chars (field.data(), field.data() + field.size(), value);
    if (field.empty() || result.ec != std::errc() ||
        result.ptr != field.data() + field.size())
      fail (std::string ("bad ") + name + " \"" + std::string (field) + "\"");
    if (std::isnan (value))
      fail (std::string (name) + " is NaN");
    return value;
  }

  /** The dimension in \a field. */
  int
  parseDimension (std::string_view field) const
  {
    int dimension = 0;
    const auto result =
        std::from_chars (field.data(), field.data() + field.size(), dimension);
    if (field.empty() || result.ec != std::errc() ||
        result.ptr != field.data() + field.size())
      fail ("bad dimension \"" + std::string (field) + "\"");
    if (dimension < 0)
      fail ("negative dimension");
    return dimension;
  }

  PersistenceInterval
  makeInterval (int dimension, double birth, double death) const
  {
    if (const char* problem = intervalProblem (dimension, birth, death))
      fail (problem);
    return {dimension, birth, death};
  }

private:
  std::istream& in_;
  const std::string& source_;
  std::string line_;
  std::string_view text_;
  std::size_t number_ = 0;
  bool at_end_ = false;
};

bool
isRipserFirstLine (std::string_view line)
{
  return std::any_of (
      std::begin (RIPSER_FIRST_LINES),
      std::end (RIPSER_FIRST_LINES),
      [&] (std::string_view prefix) { return startsWith (line, prefix); });
}

/** Reads the CSV lines after the header. */
PersistenceDiagram
readCSV (LineReader& reader)
{
  PersistenceDiagram diagram;
  while (reader.nextLine()) {
    const auto fields = splitFields (reader.text());
    if (fields.size() != CSV_COLUMNS)
      reader.fail ("expected " + std::to_string (CSV_COLUMNS) + " columns, found " +
                   std::to_string (fields.size()));
    diagram.push_back (reader.makeInterval (reader.parseDimension (fields[0]),
                                            reader.parseValue (fields[1], "birth"),
                                            reader.parseValue (fields[2], "death")));
  }
  return diagram;
}

/** Reads Ripser's output from its current (first) line on. */
PersistenceDiagram
readRipser (LineReader& reader)
{
  PersistenceDiagram diagram;
  int dimension = -1;
  do {
    const std::string_view text = reader.text();
    if (startsWith (text, RIPSER_INTERVALS)) {
      const std::string_view rest = text.substr (RIPSER_INTERVALS.size());
      if (rest.empty() || rest.back() != ':')
        reader.fail ("expected \"persistence intervals in dim <k>:\"");
      dimension = reader.parseDimension (trim (rest.substr (0, rest.size() - 1)));
    }
    else if (text.front() == '[') {
      if (dimension < 0)
        reader.fail ("interval before any \"persistence intervals in dim <k>:\" line");
      const std::string_view inside = text.substr (1, text.size() - 2);
      const auto comma = inside.find (',');
      if (text.back() != ')' || comma == std::string_view::npos ||
          inside.find (',', comma + 1) != std::string_view::npos)
        reader.fail ("expected an interval \"[birth,death)\"");
      const std::string_view death_field = trim (inside.substr (comma + 1));
      const double birth = reader.parseValue (trim (inside.substr (0, comma)), "birth");
      const double death = death_field.empty()
                               ? std::numeric_limits<double>::infinity()
                               : reader.parseValue (death_field, "death");
      diagram.push_back (reader.makeInterval (dimension, birth, death));
    }
    else if (dimension >= 0)
      reader.fail ("expected an interval \"[birth,death)\"");
  }
  while (reader.nextLine());
  if (dimension < 0)
    reader.fail ("no \"persistence intervals in dim <k>:\" line in Ripser's output");
  return diagram;
}

PersistenceDiagram
readDiagramFrom (std::istream& in, const std::string& source)
{
  LineReader reader (in, source);
  if (!reader.nextLine())
    reader.fail ("empty input, expected the header \"dim,birth,death\"");
  if (reader.text() == CSV_HEADER)
    return readCSV (reader);
  if (isRipserFirstLine (reader.text()))
    return readRipser (reader);
  reader.fail ("expected the header \"dim,birth,death\" or Ripser's output");
}

/** Longest text of a filtration value: a double's shortest form takes at most 24. */
constexpr std::size_t MAX_VALUE_TEXT = 32;

/** Writes formatFiltrationValue() of \a value at \a at, which has room for
 * MAX_VALUE_TEXT characters, and returns the end of the text. */
char*
printFiltrationValue (char* at, double value)
{
  if (value == std::numeric_limits<double>::infinity())
    return std::copy_n ("inf", 3, at);
  return std::to_chars (at, at + MAX_VALUE_TEXT, value).ptr;
}

} // namespace

std::string
formatFiltrationValue (double value)
{
  char buffer[MAX_VALUE_TEXT];
  return std::string (buffer, printFiltrationValue (buffer, value));
}

void
writeDiagramCSV (std::ostream& out, const PersistenceDiagram& diagram)
{
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto& interval = diagram[i];
    if (const char* problem =
            intervalProblem (interval.dimension, interval.birth, interval.death))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "interval " << i << " (dim " << interval.dimension
                                       << ", birth " << interval.birth << ", death "
                                       << interval.death << "): " << problem);
  }
  const auto less = [] (const PersistenceInterval& a, const PersistenceInterval& b) {
    return std::tie (a.dimension, a.birth, a.death) <
           std::tie (b.dimension, b.birth, b.death);
  };
  // The engines give H0 sorted already: only what follows needs a sort, then a merge.
  PersistenceDiagram sorted = diagram;
  const auto unsorted = std::is_sorted_until (sorted.begin(), sorted.end(), less);
  std::sort (unsorted, sorted.end(), less);
  std::inplace_merge (sorted.begin(), unsorted, sorted.end(), less);
  // One string, then one write: ten times faster than the stream's formatting.
  std::string text = std::string (CSV_HEADER) + '\n';
  text.reserve (text.size() + sorted.size() * (8 + 2 * MAX_VALUE_TEXT));
  char line[16 + 2 * MAX_VALUE_TEXT];
  for (const auto& interval : sorted) {
    char* at = std::to_chars (line, line + 16, interval.dimension).ptr;
    *at++ = ',';
    at = printFiltrationValue (at, interval.birth);
    *at++ = ',';
    at = printFiltrationValue (at, interval.death);
    *at++ = '\n';
    text.append (line, at);
  }
  out.write (text.data(), static_cast<std::streamsize> (text.size()));
}

void
saveDiagramCSV (const std::string& path, const PersistenceDiagram& diagram)
{
  writeFileAtomically (path,
                       [&] (std::ostream& out) { writeDiagramCSV (out, diagram); });
}

PersistenceDiagram
readDiagram (std::istream& in)
{
  return readDiagramFrom (in, "");
}

PersistenceDiagram
loadDiagram (const std::string& path)
{
  std::ifstream in (path);
  if (!in)
    PCL_THROW_EXCEPTION (pcl::IOException, "cannot open " << path);
  return readDiagramFrom (in, path);
}

} // namespace tda
} // namespace pcl
