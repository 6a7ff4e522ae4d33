#include <pcl/tda/apps/csv_fields.h>
#include <pcl/exceptions.h>

#include <charconv>

namespace pcl {
namespace tda {

std::vector<std::string>
splitCSVLine (const std::string& line)
{
  std::string text = line;
  if (!text.empty() && text.back() == '\r')
    text.pop_back();
  std::vector<std::string> fields (1);
  bool quoted = false; // inside a quoted field
  bool closed = false; // after the closing quote of a field
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c != '"')
        fields.back() += c;
      else if (i + 1 < text.size() && text[i + 1] == '"')
        fields.back() += text[++i];
      else {
        quoted = false;
        closed = true;
      }
    }
    else if (c == ',') {
      fields.emplace_back();
      closed = false;
    }
    else if (closed) {
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "text after the closing quote of field " << fields.size());
    }
    else if (c == '"' && fields.back().empty())
      quoted = true;
    else
      fields.back() += c;
  }
  if (quoted)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "the quote of field " << fields.size() << " is not closed");
  return fields;
}

std::string
csvField (const std::string& text)
{
  if (text.find_first_of (",\"\r\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"')
      quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

std::string
formatNumber (double value)
{
  char buffer[32];
  return {buffer, std::to_chars (buffer, buffer + sizeof (buffer), value + 0.0).ptr};
}

std::string
formatNumber (float value)
{
  char buffer[32];
  return {buffer, std::to_chars (buffer, buffer + sizeof (buffer), value + 0.0f).ptr};
}

void
skipByteOrderMark (std::istream& in)
{
  char start[3];
  if (in.read (start, 3) && std::string (start, 3) == "\xEF\xBB\xBF")
    return;
  in.clear();
  in.seekg (0);
}

} // namespace tda
} // namespace pcl
