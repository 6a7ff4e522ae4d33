#pragma once

#include <pcl/tda/common/persistence_diagram.h>

#include <istream>
#include <ostream>
#include <string>

namespace pcl {
namespace tda {

/** \brief Writes \a diagram as CSV: the header line `dim,birth,death`, then one line
 * per interval sorted by (dimension, birth, death), `inf` for an essential class.
 *
 * Values are printed in the shortest form that reads back to the same double, so
 * that readDiagram() restores the diagram exactly.
 * \throws pcl::BadArgumentException when \a diagram holds an interval that
 * readDiagram() would refuse (negative dimension, NaN, infinite birth, death
 * smaller than birth)
 */
void
writeDiagramCSV (std::ostream& out, const PersistenceDiagram& diagram);

/** \brief Saves \a diagram to the file \a path in the format of writeDiagramCSV(),
 * atomically: the file holds either its old content or the whole diagram.
 * \throws pcl::IOException when the file cannot be written
 * \throws pcl::BadArgumentException as writeDiagramCSV()
 */
void
saveDiagramCSV (const std::string& path, const PersistenceDiagram& diagram);

/** \brief Reads a diagram written by writeDiagramCSV() or printed by Ripser, telling
 * them apart by their first non-blank line.
 *
 * CSV needs the header line `dim,birth,death`; Ripser's output is recognised by
 * its first line (`point cloud with ...`, `distance matrix with ...`,
 * `value range: ...` or `persistence intervals in dim k:`), and its ` [b,d)` and
 * ` [b, )` lines are read under the last `persistence intervals in dim k:` line.
 * Infinity is written `inf` or `infinity` in any case. Blank lines are skipped and
 * zero-length intervals are kept.
 * \throws pcl::IOException naming the line number and its text when the input is
 * malformed: missing header, wrong number of columns, a bad or NaN number, a
 * negative dimension, an infinite birth or a death smaller than its birth
 */
PersistenceDiagram
readDiagram (std::istream& in);

/** \brief Reads the diagram in the file \a path as readDiagram() does.
 * \throws pcl::IOException when the file cannot be opened or is malformed
 */
PersistenceDiagram
loadDiagram (const std::string& path);

/** \brief The shortest text that reads back as exactly \a value ("inf" for
 * infinity): how the CSV writer and the diagram comparison print values. */
std::string
formatFiltrationValue (double value);

} // namespace tda
} // namespace pcl
