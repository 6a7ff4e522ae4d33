#pragma once

#include <istream>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Splits one line of a CSV file into its fields, RFC 4180 style: fields are
 * separated by commas, a field in double quotes may hold commas, and "" in it
 * stands for one quote. A carriage return at the end of the line is dropped; spaces
 * are kept.
 * \throws pcl::BadArgumentException on a quote that is not closed, or text after a
 * closing quote */
std::vector<std::string>
splitCSVLine (const std::string& line);

/** \brief \a text as a CSV field: as it is, or in double quotes (quotes doubled)
 * when it holds a comma, a quote or a line break, so that splitCSVLine() gives it
 * back. */
std::string
csvField (const std::string& text);

/** \brief Skips the UTF-8 byte order mark at the start of the file \a in (opened,
 * not read yet), where there is one: spreadsheets save "CSV UTF-8" with it. */
void
skipByteOrderMark (std::istream& in);

/** \brief \a value as the shortest decimal that reads back as the same value,
 * whatever the locale (0 for -0), for a CSV field. */
std::string
formatNumber (double value);

/** \brief \a value as the shortest decimal that reads back as the same float (0 for
 * -0). */
std::string
formatNumber (float value);

} // namespace tda
} // namespace pcl
