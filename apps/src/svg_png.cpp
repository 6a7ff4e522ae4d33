#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/exceptions.h>

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace pcl {
namespace tda {

std::string
pngBesideSVG (const std::string& svg_path)
{
  const std::string svg = ".svg";
  if (svg_path.size() > svg.size() &&
      svg_path.compare (svg_path.size() - svg.size(), svg.size(), svg) == 0)
    return svg_path.substr (0, svg_path.size() - svg.size()) + ".png";
  return svg_path + ".png";
}

std::string
pngBesideSVGWithPNG (const std::string& svg_path, const std::string& png_path)
{
  return svg_path.empty() || png_path.empty() ? std::string() : pngBesideSVG (svg_path);
}

void
renderSVGToPNG (const std::string& svg_path, const std::string& png_path)
{
  replaceFileAtomically (png_path, [&svg_path] (const std::string& temporary) {
    const char* arguments[] = {"rsvg-convert",
                               "--background-color",
                               "white",
                               "--format",
                               "png",
                               "--output",
                               temporary.c_str(),
                               svg_path.c_str(),
                               nullptr};
    pid_t child;
    const int spawned = ::posix_spawnp (&child,
                                        arguments[0],
                                        nullptr,
                                        nullptr,
                                        const_cast<char* const*> (arguments),
                                        environ);
    if (spawned != 0)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "Cannot run rsvg-convert (Debian package librsvg2-bin) "
                           "to render the SVG picture "
                               << svg_path << ": " << std::strerror (spawned));
    int status = 0;
    while (::waitpid (child, &status, 0) < 0)
      if (errno != EINTR)
        return false;
    if (!WIFEXITED (status) || WEXITSTATUS (status) != 0)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "rsvg-convert could not render the SVG picture "
                               << svg_path << " (see its message above)");
    return true;
  });
}

} // namespace tda
} // namespace pcl
