#include <pcl/tda/apps/rgb_image.h>
#include <pcl/tda/apps/viewer_screenshot.h>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

namespace pcl {
namespace tda {

void
saveWindowPicture (vtkRenderWindow* window, const std::string& path)
{
  window->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput (window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff(); // the back buffer holds the picture off-screen too
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  const int* size = image->GetDimensions();
  const auto* pixels = static_cast<const unsigned char*> (image->GetScalarPointer());
  RGBImage picture (size[0], size[1], {0, 0, 0});
  // VTK's rows go from the bottom up.
  for (int y = 0; y < size[1]; ++y)
    for (int x = 0; x < size[0]; ++x) {
      const unsigned char* pixel = pixels + 3 * (y * size[0] + x);
      picture.set (x, size[1] - 1 - y, {pixel[0], pixel[1], pixel[2]});
    }
  picture.savePNG (path);
}

} // namespace tda
} // namespace pcl
