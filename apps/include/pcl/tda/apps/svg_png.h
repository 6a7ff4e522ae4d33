#pragma once

#include <string>

namespace pcl {
namespace tda {

/** \brief The PNG picture that a tool's -png switch writes beside the SVG picture
 * \a svg_path: its name with ".png" for ".svg" (or ".png" added). */
std::string
pngBesideSVG (const std::string& svg_path);

/** \brief The PNG that pcl_tda_regions and pcl_tda_holes write beside their -svg
 * picture \a svg_path when their -png picture \a png_path is asked for too:
 * pngBesideSVG() of it, or "" when either is not given. */
std::string
pngBesideSVGWithPNG (const std::string& svg_path, const std::string& png_path);

/** \brief Renders the SVG picture \a svg_path at its own size, on white, to the PNG
 * picture \a png_path, atomically, with librsvg's rsvg-convert (Debian package
 * librsvg2-bin): the tools' pictures for programs that do not read SVG. A separate
 * process, so that the tools do not load librsvg, cairo and their dozens of
 * libraries at every start for a picture they rarely draw.
 * \throws pcl::IOException when the SVG cannot be read or rendered, or the PNG
 * written */
void
renderSVGToPNG (const std::string& svg_path, const std::string& png_path);

} // namespace tda
} // namespace pcl
