#include <pcl/tda/apps/descriptor_list.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <sstream>

namespace pcl {
namespace tda {
namespace {

std::vector<std::string>
split (const std::string& text, char separator)
{
  std::vector<std::string> pieces (1);
  for (const char c : text)
    if (c == separator)
      pieces.emplace_back();
    else
      pieces.back() += c;
  return pieces;
}

std::string
knownNames ()
{
  std::string known;
  for (const std::string& name : viewDescriptorNames())
    known += (known.empty() ? "" : ", ") + name;
  return known;
}

} // namespace

std::vector<DescriptorSpec>
parseDescriptorList (const std::string& list)
{
  std::vector<DescriptorSpec> specs;
  for (const std::string& name : split (list, ',')) {
    if (name.empty())
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "-descriptors has an empty name in '" << list << "'.");
    DescriptorSpec spec{name, split (name, '+')};
    for (std::size_t k = 0; k < spec.parts.size(); ++k) {
      if (!isViewDescriptor (spec.parts[k]))
        PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                             "Unknown descriptor '" << spec.parts[k]
                                                    << "' in -descriptors"
                                                    << " (known: " << knownNames()
                                                    << "; join them with + to "
                                                       "combine).");
      if (std::find (spec.parts.begin(), spec.parts.begin() + k, spec.parts[k]) !=
          spec.parts.begin() + k)
        PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                             "Descriptor " << name << " combines " << spec.parts[k]
                                           << " with itself.");
    }
    for (const DescriptorSpec& other : specs)
      if (other.name == name)
        PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                             "Descriptor " << name << " is listed twice.");
    specs.push_back (spec);
  }
  return specs;
}

std::vector<std::string>
neededViewDescriptors (const std::vector<DescriptorSpec>& specs)
{
  std::vector<std::string> names;
  for (const DescriptorSpec& spec : specs)
    for (const std::string& part : spec.parts)
      if (std::find (names.begin(), names.end(), part) == names.end())
        names.push_back (part);
  return names;
}

DescriptorTable
assembleDescriptor (const DescriptorSpec& spec,
                    const std::vector<std::string>& names,
                    const std::vector<std::vector<ViewDescriptor>>& computed)
{
  std::vector<std::size_t> columns;
  for (const std::string& part : spec.parts)
    columns.push_back (static_cast<std::size_t> (
        std::find (names.begin(), names.end(), part) - names.begin()));
  DescriptorTable table;
  table.parts.assign (columns.size(), 0);
  const std::size_t views = computed.size();
  table.rows.resize (views);
  table.failures.resize (views);
  table.milliseconds.assign (views, 0.0);
  for (std::size_t i = 0; i < views; ++i) {
    double normals = 0.0;
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const ViewDescriptor& part = computed[i].at (columns[k]);
      table.milliseconds[i] += part.milliseconds;
      normals = std::max (normals, part.normal_milliseconds);
      if (!part.failure.empty() && table.failures[i].empty())
        table.failures[i] = spec.parts[k] + ": " + part.failure;
      if (part.values.empty())
        continue;
      if (table.parts[k] != 0 && table.parts[k] != part.values.size())
        PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                             "Descriptor " << spec.parts[k] << " has "
                                           << part.values.size() << " values on one "
                                           << "view and " << table.parts[k]
                                           << " on another.");
      table.parts[k] = part.values.size();
    }
    table.milliseconds[i] += normals;
  }
  for (std::size_t i = 0; i < views; ++i) {
    if (!table.failures[i].empty())
      continue;
    for (const std::size_t column : columns) {
      const std::vector<float>& values = computed[i][column].values;
      table.rows[i].insert (table.rows[i].end(), values.begin(), values.end());
    }
  }
  if (std::find (table.parts.begin(), table.parts.end(), 0) == table.parts.end())
    for (const std::size_t part : table.parts)
      table.dimension += part;
  else
    table.parts.clear(); // a part failed everywhere: so does the descriptor
  return table;
}

} // namespace tda
} // namespace pcl
