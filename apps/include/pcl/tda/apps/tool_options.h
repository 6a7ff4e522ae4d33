#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The values a number option accepts: finite numbers from \a minimum
 * (excluded when \a above_minimum) up to \a maximum (excluded when
 * \a below_maximum). */
struct NumberRange {
  double minimum = 0.0;
  bool above_minimum = false;
  double maximum = std::numeric_limits<double>::max();
  bool below_maximum = false;

  /** \brief Numbers > \a minimum, up to \a maximum. */
  static NumberRange
  above (double minimum, double maximum = std::numeric_limits<double>::max())
  {
    return {minimum, true, maximum, false};
  }

  /** \brief Numbers >= \a minimum, up to \a maximum. */
  static NumberRange
  atLeast (double minimum, double maximum = std::numeric_limits<double>::max())
  {
    return {minimum, false, maximum, false};
  }

  /** \brief Numbers >= \a minimum and < \a maximum. */
  static NumberRange
  atLeastBelow (double minimum, double maximum)
  {
    return {minimum, false, maximum, true};
  }
};

/** \brief The strict command line of the tools: positional arguments, options with
 * a value ("-radius 0.01") and switches ("-json"). Every argument that starts with
 * '-' must be a declared option, an option must have a value, numbers must be whole
 * ("1e-3", not "abc" or "1x") and in range, and an option is given at most once;
 * every error names the option and the value. */
class ToolCommandLine {
public:
  /** \brief Declares "-name X" for a number in \a range, written to \a value.
   * \a required: the tool cannot run without it. */
  void
  addNumber (const std::string& name,
             double& value,
             NumberRange range,
             bool required = false);

  /** \brief Declares "-name N" for an integer from \a minimum to \a maximum. */
  void
  addInteger (const std::string& name, long& value, long minimum, long maximum);

  /** \brief Declares "-name M" for a memory size of M MiB (M > 0), written to
   * \a bytes in bytes; \a bytes keeps its value (defaultMemoryLimit(), say) when
   * the option is not given. */
  void
  addMemory (const std::string& name, std::size_t& bytes);

  /** \brief Declares "-name TEXT" (not empty), e.g. a file name. */
  void
  addText (const std::string& name, std::string& value);

  /** \brief Declares the switch "-name", which sets \a value to true. */
  void
  addSwitch (const std::string& name, bool& value);

  /** \brief Parses the arguments after the program name, filling the declared
   * values, and returns the positional arguments.
   * \throws pcl::BadArgumentException naming the option and value at fault */
  std::vector<std::string>
  parse (int argc, const char* const* argv);

  /** \brief True when the last parse() met option \a name. */
  bool
  given (const std::string& name) const
  {
    return given_.count (name) != 0;
  }

private:
  /** One declared option and where its value goes. */
  struct Option {
    std::variant<double*, long*, std::size_t*, std::string*, bool*> value;
    NumberRange range;
    long minimum = 0, maximum = 0;
    bool required = false;
  };

  /** Stores \a text as the value of \a option, checking it. */
  void
  store (const std::string& name, const Option& option, const std::string& text) const;

  std::map<std::string, Option> options_;
  std::set<std::string> given_;
};

/** \brief The finite decimal number \a text spells as a whole (std::strtod: no
 * leading space, nothing after it, not hexadecimal), or none. */
std::optional<double>
parseWholeNumber (const std::string& text);

/** \brief The integer \a text spells as a whole (std::strtol, base 10: no leading
 * space, nothing after it, within the range of long), or none. */
std::optional<long>
parseWholeInteger (const std::string& text);

/** \brief True when one of the arguments asks for help ("-h" or "--help"): a tool
 * then prints its help only and exits with 0. */
bool
helpRequested (int argc, const char* const* argv);

/** \brief A positional argument of a tool: its role ("input") and, for a file, the
 * extension it must end in (".pcd"; "" for any argument). */
struct ToolArgument {
  std::string role;
  std::string extension;
};

/** \brief Requires \a path, the value of option \a option ("" when it is not given),
 * to end in \a extension (".svg").
 * \throws pcl::BadArgumentException "-svg needs a .svg file (got 'x.txt')." */
void
checkOptionExtension (const std::string& option,
                      const std::string& path,
                      const std::string& extension);

/** \brief Checks the positional arguments \a arguments (of ToolCommandLine::parse())
 * against the \a expected ones: as many, each file with its extension.
 * \throws pcl::BadArgumentException saying what is expected */
void
checkArguments (const std::vector<std::string>& arguments,
                const std::vector<ToolArgument>& expected);

} // namespace tda
} // namespace pcl
