// The tools' -png: SVG pictures rendered as PNG by librsvg (renderSVGToPNG()), at
// their size and in their colours; unreadable SVG refused with no PNG written; and
// pcl_tda_segment and pcl_tda_barcode -png writing F.png beside each F.svg.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "png_picture.h"
#include "tool_runner.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

using pcl::tda::test::exists;
using pcl::tda::test::Picture;
using pcl::tda::test::readPNG;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;

namespace {

std::string
temporaryPath (const std::string& name)
{
  return pcl::tda::test::temporaryPath ("svg_png", name);
}

TEST (SVGToPNG, NamesThePictureBesideTheSVG)
{
  EXPECT_EQ (pcl::tda::pngBesideSVG ("out/barcode.svg"), "out/barcode.png");
  EXPECT_EQ (pcl::tda::pngBesideSVG ("picture"), "picture.png");
  EXPECT_EQ (pcl::tda::pngBesideSVG (".svg"), ".svg.png");
}

TEST (SVGToPNG, RendersABarcodeAtItsSizeInItsColours)
{
  // Two long H0 bars and an essential one: the first bar colour (#1f77b4) and the
  // essential classes' red (#d62728).
  const pcl::tda::PersistenceDiagram diagram{
      {0, 0.0, 0.5}, {0, 0.0, 0.8}, {0, 0.0, std::numeric_limits<double>::infinity()}};
  pcl::tda::PlotOptions plot;
  plot.width = 640;
  plot.max_value = 1.0;
  const std::string svg = temporaryPath ("bars.svg"), png = temporaryPath ("bars.png");
  pcl::tda::saveBarcodeSVG (svg, diagram, plot);
  pcl::tda::renderSVGToPNG (svg, png);
  const Picture picture = readPNG (png);
  EXPECT_EQ (picture.width, 640u);
  EXPECT_GT (picture.height, 50u);
  EXPECT_GT (picture.count ({0x1f, 0x77, 0xb4}), 300u);
  EXPECT_GT (picture.count ({0xd6, 0x27, 0x28}), 20u);
  EXPECT_GT (picture.count ({255, 255, 255}), picture.width * picture.height / 3);
}

TEST (SVGToPNG, RefusesWhatIsNoSVG)
{
  const std::string svg = temporaryPath ("broken.svg"), png = temporaryPath ("x.png");
  std::remove (png.c_str());
  std::ofstream (svg) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\"";
  EXPECT_THROW (pcl::tda::renderSVGToPNG (svg, png), pcl::IOException);
  EXPECT_THROW (pcl::tda::renderSVGToPNG (temporaryPath ("missing.svg"), png),
                pcl::IOException);
  EXPECT_FALSE (exists (png));
}

TEST (SVGToPNG, SegmentToolWritesThePNGBesideItsSVG)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 40; ++i) // two groups of 20 points, 1 m apart
    cloud.push_back (pcl::PointXYZ (0.01f * (i % 20) + (i < 20 ? 0.0f : 1.0f), 0, 1));
  const std::string in = temporaryPath ("in.pcd"), out = temporaryPath ("out.pcd"),
                    svg = temporaryPath ("h0.svg"), png = temporaryPath ("h0.png");
  pcl::io::savePCDFileBinary (in, cloud);
  std::remove (png.c_str());
  const std::string tool = std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_segment ";
  RunResult result = run (tool + in + " " + out + " -radius 0.05 -plane 0 -png");
  EXPECT_EQ (result.exit_code, 1);
  EXPECT_NE (result.output.find ("-png has no use without -svg"), std::string::npos)
      << result.output;
  result = run (tool + in + " " + out + " -radius 0.05 -plane 0 -svg " + svg + " -png");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const Picture picture = readPNG (png);
  EXPECT_EQ (picture.width, 800u); // the barcode's default width
  EXPECT_GT (picture.numColors(), 3u);
  EXPECT_GT (picture.count ({0xd6, 0x27, 0x28}), 20u); // the essential classes, cut
}

TEST (SVGToPNG, BarcodeToolWritesAPNGBesideEachSVG)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 60; ++i) // a circle: one long H1 bar
    cloud.push_back (pcl::PointXYZ (std::cos (i * 0.1047f), std::sin (i * 0.1047f), 0));
  const std::string in = temporaryPath ("circle.pcd"), csv = temporaryPath ("d.csv"),
                    bars = temporaryPath ("bars.svg"),
                    points = temporaryPath ("pd.svg");
  pcl::io::savePCDFileBinary (in, cloud);
  const std::string tool =
      std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_barcode " + in + " " + csv;
  RunResult result = run (tool + " -radius 0.5 -png");
  EXPECT_EQ (result.exit_code, 1);
  EXPECT_NE (result.output.find ("-png has no use without -svg or -diagram"),
             std::string::npos)
      << result.output;
  result = run (tool + " -radius 0.5 -svg " + bars + " -diagram " + points + " -png");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  for (const std::string& svg : {bars, points}) {
    const Picture picture = readPNG (pcl::tda::pngBesideSVG (svg));
    EXPECT_EQ (picture.width, 800u) << svg;
    EXPECT_GT (picture.numColors(), 3u) << svg;
  }
}

} // namespace
