// libFuzzer target of the tools' option parser: the input is a command line, one
// argument per line. ToolCommandLine::parse() accepts it with every value in range,
// or throws pcl::BadArgumentException; it never crashes.

#include <pcl/tda/apps/tool_options.h>
#include <pcl/exceptions.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> arguments{"tool"};
  std::istringstream lines (std::string (reinterpret_cast<const char*> (data), size));
  for (std::string line; std::getline (lines, line);)
    arguments.push_back (line);
  std::vector<const char*> argv;
  for (const std::string& argument : arguments)
    argv.push_back (argument.c_str());
  const int argc = static_cast<int> (argv.size());

  double radius = 0.0, leaf = 0.0;
  long dimension = 1, count = 1;
  std::string svg;
  bool json = false;
  pcl::tda::ToolCommandLine command_line;
  command_line.addNumber ("-radius", radius, pcl::tda::NumberRange::above (0.0), true);
  command_line.addNumber ("-leaf", leaf, pcl::tda::NumberRange::atLeast (0.0));
  command_line.addInteger ("-dim", dimension, 0, 1);
  command_line.addInteger ("-n", count, 1, 10000000);
  command_line.addText ("-svg", svg);
  command_line.addSwitch ("-json", json);
  pcl::tda::helpRequested (argc, argv.data());
  try {
    pcl::tda::checkArguments (command_line.parse (argc, argv.data()),
                              {{"input", ".pcd"}, {"output", ".csv"}});
    if (!(radius > 0.0 && std::isfinite (radius)) || !(leaf >= 0.0) ||
        !std::isfinite (leaf) || dimension < 0 || dimension > 1 || count < 1 ||
        count > 10000000 || (command_line.given ("-svg") && svg.empty()))
      __builtin_trap();
  }
  catch (const pcl::BadArgumentException&) {
  }
  return 0;
}
