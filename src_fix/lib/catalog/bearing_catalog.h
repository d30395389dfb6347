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

// One catalog entry: what its source publishes, no more (doc/bearing_catalog.md). Geometry
// Nb, Db and the pitch diameter (Dpw, or Dext and Dinn: Dpw = (Dext + Dinn)/2), optionally
// Rcext, Rcinn; and/or the maker's defect-frequency factors BPFO, BPFI [BSF, FTF] (multiples of
// the shaft frequency). A value not given is 0. Lengths in m.
struct CatalogEntry {
  std::string name, path;           // the entry read (an alias's target), its file
  std::string requested;            // the name asked for (an alias, or name itself)
  std::vector<std::string> others;  // an alias: the other entries that share its name
  int nb = 0;
  double db = 0, dext = 0, dinn = 0, rc_ext = 0, rc_inn = 0, dpw = 0;  // m; 0: not given
  double bpfo = 0, bpfi = 0, bsf = 0, ftf = 0;                         // x fr; 0: not given
  std::vector<std::pair<std::string, std::string>> variables;          // every line, in file order

  bool has(const std::string &variable) const;  // a line of the file gives it
  // The pitch diameter: Dpw, else (Dext + Dinn)/2, else 0 (not published).
  double pitch_diameter() const;
  bool has_factors() const { return bpfo > 0; }  // BPFO and BPFI come together
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
// The entry NAME of DIR, an alias resolved (one step: an alias names an entry). A name that is
// not a catalog name or not in DIR, a file that refers elsewhere ("refer NAME..."), or a
// malformed file is an error; the messages of a missing name are the caller's (this one says
// "bearing 'NAME' is not in the catalog DIR").
CatalogEntry read_entry(const std::string &dir, const std::string &name);
// What an alias or refer file of DIR says, for messages: "" for an entry.
struct NameFile {
  std::string kind;                // "alias", "refer" or "" (an entry)
  std::vector<std::string> names;  // alias: target then others; refer: the names it refers to
};
NameFile read_name_file(const std::string &path);

// What the deck needs that the entry does not give. The simulation needs Nb, Db, Dext and
// Dinn; Dext and Dinn follow from a pitch diameter Dpw as Dpw + Db and Dpw - Db (zero
// clearance). given(X) is the -var value of deck variable X, or "" when not given. Returns the
// variables to define (derived Dext, Dinn) and their catalog copies, or an error naming what
// is missing and how to give it.
struct DeckGeometry {
  std::vector<std::pair<std::string, std::string>> define, copies;
  std::string error;
};
DeckGeometry deck_geometry_of(const CatalogEntry *entry,
                              const std::vector<std::pair<std::string, std::string>> &given);

// "%.6g": how the reader's messages print numbers.
std::string format_value(double v);

}  // namespace ohmdem::catalog

#endif
