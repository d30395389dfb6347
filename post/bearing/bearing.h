// SPDX-License-Identifier: GPL-2.0-or-later
// Rolling-bearing geometry, the bearing catalog it comes from, and the kinematic (defect)
// frequencies (Harris' formulas for a rotating inner ring and a fixed outer ring).
#ifndef OHMDEM_POST_BEARING_H
#define OHMDEM_POST_BEARING_H

#include <optional>
#include <string>
#include <vector>

#include "catalog/bearing_catalog.h"

namespace ohmdem::post {

// A maker's defect-frequency factors: BPFO, BPFI, BSF, FTF as multiples of the shaft frequency.
struct DefectFactors {
  double bpfo = 0, bpfi = 0, bsf = 0, ftf = 0;
};

// A bearing as far as its source publishes it: the ball set (nb, db, dp), or factors, or both
// (then the factors give the frequencies). db = dp = 0: not published (factors only).
struct BearingGeometry {
  std::string name;              // catalog name or "custom"
  int nb = 0;                    // number of balls
  double db = 0;                 // ball diameter (m)
  double dp = 0;                 // pitch diameter (m)
  double contact_angle_deg = 0;  // contact angle beta (degrees)
  std::optional<DefectFactors> factors;
};

// The setting {bearing.factors}, "BPFO,BPFI,BSF,FTF"; BSF and FTF may be left out
// ("BPFO,BPFI"): they follow from BPFO and BPFI (Z = BPFO + BPFI). Throws SettingError.
DefectFactors parse_factors(const std::string &text);
// BSF and FTF of factors that give BPFO and BPFI only (zero contact angle folded into d/D).
DefectFactors complete_factors(DefectFactors f);

// One file of the bearing catalog (inputs/bearings, doc/bearing_catalog.md), read by
// src_fix/lib/catalog, the reader the engine's command bearing_catalog uses too. The pitch
// diameter is (Dext + Dinn)/2, as in the deck.
struct CatalogEntry : catalog::CatalogEntry {
  // Throws SettingError when the entry gives neither a whole ball set nor factors (what is
  // missing).
  BearingGeometry geometry() const;
  // What the entry gives, unchecked (to complete with {geometry.dp}).
  BearingGeometry partial() const;
};

// The catalog folder: $OHMDEM_CATALOG if set and not empty, else the installed catalog
// (PREFIX/share/ohmdem/inputs/bearings) when this executable is the installed one, else the
// source tree's inputs/bearings (compile-time default).
std::string default_catalog_dir();
// Entries of DIR: regular files whose name has no dot, sorted. Throws Error if DIR is no folder.
std::vector<std::string> catalog_names(const std::string &dir);
// Parses one catalog file; any other line form, a missing or non-positive value is an Error
// naming the file and line.
CatalogEntry read_catalog_file(const std::string &path, const std::string &name);
// The entry NAME of DIR; an unknown name is an Error listing the known names.
CatalogEntry catalog_entry(const std::string &dir, const std::string &name);
// Geometry of NAME in the default catalog.
BearingGeometry bearing_preset(const std::string &name);

// Throws Error naming the offending quantity.
void validate(const BearingGeometry &g);

struct DefectFrequencies {
  double fr = 0;    // shaft (inner ring) frequency (Hz)
  double ftf = 0;   // fundamental train (cage) frequency
  double bpfo = 0;  // ball pass frequency, outer race
  double bpfi = 0;  // ball pass frequency, inner race
  double bsf = 0;   // ball spin frequency (relative to the cage)
};

// FTF = fr/2 (1 - d/D cos b), BPFO = Nb FTF, BPFI = Nb fr/2 (1 + d/D cos b),
// BSF = D/(2d) fr (1 - (d/D cos b)^2).
DefectFrequencies defect_frequencies(const BearingGeometry &g, double fr);

}  // namespace ohmdem::post

#endif
