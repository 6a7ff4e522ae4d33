#include <pcl/tda/common/progress_bar.h>

#include <unistd.h>

namespace pcl {
namespace tda {

ProgressBar::ProgressBar (std::string label, std::FILE* stream)
: label_ (std::move (label))
, stream_ (stream)
, enabled_ (::isatty (::fileno (stream)) != 0)
{}

ProgressBar::~ProgressBar() { finish(); }

void
ProgressBar::update (std::size_t done, std::size_t total)
{
  if (!enabled_ || finished_)
    return;
  const int percent = total == 0 ? 100 : static_cast<int> (100.0 * done / total);
  if (percent == shown_percent_)
    return;
  if (shown_percent_ < 0)
    std::fputc ('\n', stream_); // start below whatever the line holds
  shown_percent_ = percent;
  constexpr int WIDTH = 40;
  const int filled = percent * WIDTH / 100;
  std::fprintf (stream_,
                "\r%s [%.*s%*s] %3d%%",
                label_.c_str(),
                filled,
                "========================================",
                WIDTH - filled,
                "",
                percent);
  std::fflush (stream_);
}

void
ProgressBar::finish()
{
  if (!enabled_ || finished_)
    return;
  update (1, 1);
  std::fputc ('\n', stream_);
  finished_ = true;
}

} // namespace tda
} // namespace pcl
