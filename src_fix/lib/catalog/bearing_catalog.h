// SPDX-License-Identifier: GPL-2.0-or-later
// The bearing catalog (inputs/bearings, doc/bearing_catalog.md), read by the engine's command
// bearing_catalog and by ohmdem-post: one file per bearing, LIGGGHTS lines
// "variable NAME index VALUE  # source". Plain C++, no LIGGGHTS types.
#ifndef OHMDEM_CATALOG_BEARING_CATALOG_H
#define OHMDEM_CATALOG_BEARING_CATALOG_H

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ohmdem::catalog {

// Every failure of the reader; the message names the folder, or the file and line.
class CatalogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One catalog file. Required: Nb, Db, Dext, Dinn, Rcext, Rcinn (lengths in m).
struct CatalogEntry {
  std::string name, path;
  int nb = 0;
  double db = 0, dext = 0, dinn = 0, rc_ext = 0, rc_inn = 0;   // m
  std::vector<std::pair<std::string, std::string>> variables;  // every line, in file order
};

// The catalog folder when none is given: $OHMDEM_CATALOG if set and not empty, else the
// installed catalog (PREFIX/share/ohmdem/inputs/bearings) when this executable is the installed
// one, else the source tree's inputs/bearings (compiled in).
std::string default_catalog_dir();
// The catalog installed beside this executable, or "" when it runs from a build tree.
std::string installed_catalog_dir();

// A name a user may give: letters, digits, '_' and '-' (no path, no dot, nothing a shell or
// a deck would read as syntax).
bool is_catalog_name(const std::string &name);
// Entries of DIR: regular files whose name has no dot, sorted. Throws if DIR is no folder
// ("bearing catalog 'DIR' is not a readable folder").
std::vector<std::string> catalog_names(const std::string &dir);
// "a b c", or "(none)".
std::string joined_names(const std::vector<std::string> &names);
// Parses one catalog file; any other line form, a missing or non-positive value, or
// Dext <= Dinn is an error naming the file and line.
CatalogEntry read_catalog_file(const std::string &path, const std::string &name);
// "%.6g": how the reader's messages print numbers.
std::string format_value(double v);

}  // namespace ohmdem::catalog

#endif
