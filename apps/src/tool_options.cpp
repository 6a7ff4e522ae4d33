#include <pcl/tda/apps/tool_options.h>
#include <pcl/exceptions.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pcl {
namespace tda {

namespace {

/** "a number > 0", "an integer from 0 to 1", ...: what an option accepts. */
std::string
describe (const NumberRange& range)
{
  std::ostringstream text;
  text << "a number " << (range.above_minimum ? "> " : ">= ") << range.minimum;
  if (range.maximum < std::numeric_limits<double>::max())
    text << (range.below_maximum ? " and < " : " and <= ") << range.maximum;
  return text.str();
}

std::string
describe (long minimum, long maximum)
{
  std::ostringstream text;
  text << "an integer ";
  if (maximum == std::numeric_limits<long>::max())
    text << ">= " << minimum;
  else
    text << "from " << minimum << " to " << maximum;
  return text.str();
}

[[noreturn]] void
refuseValue (const std::string& name,
             const std::string& accepted,
             const std::string& text)
{
  PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                       "Option " << name << " needs " << accepted << ", not '" << text
                                 << "'.");
}

/** The largest value of a memory option, in MiB (a million TiB). */
constexpr double MAX_MEMORY_MIB = 1e12;

/** The number \a text spells, checked to be in \a range.
 * \throws pcl::BadArgumentException naming option \a name when it is not */
double
numberIn (const NumberRange& range, const std::string& name, const std::string& text)
{
  const std::optional<double> value = parseWholeNumber (text);
  if (!value || *value < range.minimum ||
      (range.above_minimum && *value == range.minimum) || *value > range.maximum ||
      (range.below_maximum && *value == range.maximum))
    refuseValue (name, describe (range), text);
  return *value;
}

/** Whether strtod or strtol, which skip leading spaces and stop at the first
 * character they cannot read, read all of \a text: a whole number has neither. */
bool
readWhole (const std::string& text, const char* end)
{
  return !text.empty() && !std::isspace (static_cast<unsigned char> (text[0])) &&
         end == text.c_str() + text.size();
}

/** Whether \a path ends in \a extension, after a name (a file name, not the
 * extension alone); any path when \a extension is "". */
bool
hasExtension (const std::string& path, const std::string& extension)
{
  return path.size() > extension.size() &&
         path.compare (path.size() - extension.size(), extension.size(), extension) ==
             0;
}

} // namespace

void
ToolCommandLine::addNumber (const std::string& name,
                            double& value,
                            NumberRange range,
                            bool required)
{
  options_[name] = Option{&value, range, 0, 0, required};
}

void
ToolCommandLine::addInteger (const std::string& name,
                             long& value,
                             long minimum,
                             long maximum)
{
  options_[name] = Option{&value, {}, minimum, maximum, false};
}

void
ToolCommandLine::addMemory (const std::string& name, std::size_t& bytes)
{
  options_[name] =
      Option{&bytes, NumberRange::above (0.0, MAX_MEMORY_MIB), 0, 0, false};
}

void
ToolCommandLine::addText (const std::string& name, std::string& value)
{
  options_[name] = Option{&value, {}, 0, 0, false};
}

void
ToolCommandLine::addSwitch (const std::string& name, bool& value)
{
  options_[name] = Option{&value, {}, 0, 0, false};
}

std::optional<double>
parseWholeNumber (const std::string& text)
{
  // strtod also reads hexadecimal ("0x10" is 16): decimal numbers only.
  if (text.find_first_of ("xX") != std::string::npos)
    return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod (text.c_str(), &end);
  if (!readWhole (text, end) || !std::isfinite (value))
    return std::nullopt;
  return value;
}

std::optional<long>
parseWholeInteger (const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol (text.c_str(), &end, 10);
  if (!readWhole (text, end) || errno == ERANGE)
    return std::nullopt;
  return value;
}

void
ToolCommandLine::store (const std::string& name,
                        const Option& option,
                        const std::string& text) const
{
  if (auto* number = std::get_if<double*> (&option.value))
    **number = numberIn (option.range, name, text);
  else if (auto* bytes = std::get_if<std::size_t*> (&option.value))
    **bytes =
        static_cast<std::size_t> (numberIn (option.range, name, text) * 1048576.0);
  else if (auto* integer = std::get_if<long*> (&option.value)) {
    const std::optional<long> value = parseWholeInteger (text);
    if (!value || *value < option.minimum || *value > option.maximum)
      refuseValue (name, describe (option.minimum, option.maximum), text);
    **integer = *value;
  }
  else {
    if (text.empty() || text[0] == '-')
      refuseValue (name, "a value", text);
    *std::get<std::string*> (option.value) = text;
  }
}

std::vector<std::string>
ToolCommandLine::parse (int argc, const char* const* argv)
{
  given_.clear();
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.empty() || argument[0] != '-') {
      positional.push_back (argument);
      continue;
    }
    const auto option = options_.find (argument);
    if (option == options_.end())
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Unknown option " << argument << " (see -h).");
    if (!given_.insert (argument).second)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option " << argument << " is given twice.");
    if (auto* on = std::get_if<bool*> (&option->second.value)) {
      **on = true;
      continue;
    }
    if (i + 1 >= argc)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option " << argument << " needs a value.");
    store (argument, option->second, argv[++i]);
  }
  for (const auto& [name, option] : options_)
    if (option.required && !given (name))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Option " << name << " is required.");
  return positional;
}

bool
helpRequested (int argc, const char* const* argv)
{
  for (int i = 1; i < argc; ++i)
    if (std::string (argv[i]) == "-h" || std::string (argv[i]) == "--help")
      return true;
  return false;
}

void
checkArguments (const std::vector<std::string>& arguments,
                const std::vector<ToolArgument>& expected)
{
  if (arguments.size() != expected.size()) {
    std::ostringstream needed;
    for (std::size_t i = 0; i < expected.size(); ++i)
      needed << (i == 0 ? "" : " and ") << "the " << expected[i].role
             << (expected[i].extension.empty() ? ""
                                               : " " + expected[i].extension + " file");
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Need "
                             << needed.str() << ", not " << arguments.size()
                             << (arguments.size() == 1 ? " argument." : " arguments."));
  }
  for (std::size_t i = 0; i < expected.size(); ++i)
    if (!hasExtension (arguments[i], expected[i].extension))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "The " << expected[i].role << " " << arguments[i]
                                  << " must be a " << expected[i].extension
                                  << " file.");
}

void
checkOptionExtension (const std::string& option,
                      const std::string& path,
                      const std::string& extension)
{
  if (!path.empty() && !hasExtension (path, extension))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         option << " needs a " << extension << " file (got '" << path
                                << "').");
}

} // namespace tda
} // namespace pcl
