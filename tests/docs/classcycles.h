#pragma once

// Classes that depend on each other: a class is a file's name without its extension (X.h and
// X.cpp together), and it depends on every class whose header its files include. A cycle (the
// link base class whose factory makes its subclasses, which include the base class) means neither
// can be understood, built or tested without the other; docs/architecture.md ("Layers") asks for
// none, and tst_layers checks the tree has none.

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QStringList>

namespace mbscope::testdocs {

// includes: each file (relative path) with the files its includes reach. Returns each group of
// classes that depend on each other in a cycle (the strongly connected components with more than
// one class), each sorted, the groups sorted by their first class.
[[nodiscard]] QList<QStringList> classCycles(const QMap<QString, QStringList> &includes);

} // namespace mbscope::testdocs
