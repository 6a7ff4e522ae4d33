#include <pcl/tda/apps/barcode_overlay.h>

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace {

/** The drawing area, in normalized viewport coordinates. */
constexpr double LEFT = 0.06, RIGHT = 0.96, BOTTOM = 0.06, TOP = 0.94;
/** Vertical space of a panel's title. */
constexpr double TITLE_HEIGHT = 0.06;

/** The longest MAX_BARS intervals of dimension \a dimension (essential first), by
 * birth. */
std::vector<PersistenceInterval>
longestBars (const PersistenceDiagram& diagram, int dimension)
{
  std::vector<PersistenceInterval> bars;
  for (const auto& interval : diagram)
    if (interval.dimension == dimension)
      bars.push_back (interval);
  const auto longer = [] (const PersistenceInterval& a, const PersistenceInterval& b) {
    return a.death - a.birth > b.death - b.birth;
  };
  if (bars.size() > BarcodeOverlay::MAX_BARS) {
    std::partial_sort (
        bars.begin(), bars.begin() + BarcodeOverlay::MAX_BARS, bars.end(), longer);
    bars.resize (BarcodeOverlay::MAX_BARS);
  }
  std::stable_sort (bars.begin(),
                    bars.end(),
                    [] (const PersistenceInterval& a, const PersistenceInterval& b) {
                      return a.birth < b.birth;
                    });
  return bars;
}

/** A 2D actor drawing \a lines, given in normalized viewport coordinates, each in
 * its colour of \a colors, \a width pixels wide. */
vtkSmartPointer<vtkActor2D>
lineActor (vtkPoints* points,
           vtkCellArray* lines,
           vtkUnsignedCharArray* colors,
           float width)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints (points);
  poly->SetLines (lines);
  poly->GetCellData()->SetScalars (colors);
  auto coordinate = vtkSmartPointer<vtkCoordinate>::New();
  coordinate->SetCoordinateSystemToNormalizedViewport();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData (poly);
  mapper->SetTransformCoordinate (coordinate);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper (mapper);
  actor->GetProperty()->SetLineWidth (width);
  return actor;
}

/** A line of text at (x, y), in normalized viewport coordinates, starting there or
 * (\a right) ending there. */
void
addLabel (vtkRenderer* renderer,
          const std::string& text,
          double x,
          double y,
          bool right = false)
{
  auto label = vtkSmartPointer<vtkTextActor>::New();
  label->SetInput (text.c_str());
  label->GetTextProperty()->SetFontSize (14);
  label->GetTextProperty()->SetColor (1.0, 1.0, 1.0);
  if (right)
    label->GetTextProperty()->SetJustificationToRight();
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->SetPosition (x, y);
  renderer->AddActor2D (label);
}

} // namespace

BarcodeOverlay::BarcodeOverlay (vtkRenderer* renderer,
                                const PersistenceDiagram& diagram,
                                double max_value)
: max_value_ (max_value)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetNumberOfComponents (3);
  const double panel_height = (TOP - BOTTOM) / 2.0;
  for (int dimension = 0; dimension <= 1; ++dimension) {
    const std::vector<PersistenceInterval> bars = longestBars (diagram, dimension);
    const double top = TOP - dimension * panel_height;
    std::size_t total = 0;
    for (const auto& interval : diagram)
      total += interval.dimension == dimension;
    addLabel (renderer,
              "H" + std::to_string (dimension) + ": " + std::to_string (total) +
                  " bars" +
                  (total > bars.size()
                       ? " (the " + std::to_string (bars.size()) + " longest drawn)"
                       : ""),
              LEFT,
              top - TITLE_HEIGHT + 0.01);
    const double pitch = (panel_height - TITLE_HEIGHT) /
                         static_cast<double> (std::max<std::size_t> (bars.size(), 8));
    const auto& color = dimension == 0 ? H0_COLOR : H1_COLOR;
    for (std::size_t k = 0; k < bars.size(); ++k) {
      const double y = top - TITLE_HEIGHT - (static_cast<double> (k) + 0.5) * pitch;
      lines->InsertNextCell (2);
      lines->InsertCellPoint (points->InsertNextPoint (
          position (std::min (bars[k].birth, max_value_)), y, 0.0));
      lines->InsertCellPoint (points->InsertNextPoint (
          position (std::min (bars[k].death, max_value_)), y, 0.0));
      colors->InsertNextTypedTuple (color.data());
    }
  }
  renderer->AddActor2D (lineActor (points, lines, colors, 3.0f));

  auto cursor = vtkSmartPointer<vtkPoints>::New();
  cursor_ = cursor;
  cursor_->InsertNextPoint (position (max_value_), BOTTOM, 0.0);
  cursor_->InsertNextPoint (position (max_value_), TOP, 0.0);
  auto cursor_line = vtkSmartPointer<vtkCellArray>::New();
  cursor_line->InsertNextCell (2);
  cursor_line->InsertCellPoint (0);
  cursor_line->InsertCellPoint (1);
  auto white = vtkSmartPointer<vtkUnsignedCharArray>::New();
  white->SetNumberOfComponents (3);
  const unsigned char WHITE[3] = {255, 255, 255};
  white->InsertNextTypedTuple (WHITE);
  renderer->AddActor2D (lineActor (cursor, cursor_line, white, 1.0f));
  std::ostringstream end;
  end << max_value_;
  addLabel (renderer, "0", LEFT, 0.01);
  addLabel (renderer, "radius", (LEFT + RIGHT) / 2.0 - 0.05, 0.01);
  addLabel (renderer, end.str(), RIGHT, 0.01, true);
}

void
BarcodeOverlay::setRadius (double radius)
{
  const double x = position (std::min (radius, max_value_));
  cursor_->SetPoint (0, x, BOTTOM, 0.0);
  cursor_->SetPoint (1, x, TOP, 0.0);
  cursor_->Modified();
}

double
BarcodeOverlay::position (double value) const
{
  return LEFT + (RIGHT - LEFT) * value / max_value_;
}

} // namespace tda
} // namespace pcl
