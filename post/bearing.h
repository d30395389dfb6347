// Rolling-bearing geometry and its kinematic (defect) frequencies, Harris' formulas for a
// rotating inner ring and a fixed outer ring.
#ifndef OHMDEM_POST_BEARING_H
#define OHMDEM_POST_BEARING_H

#include <string>
#include <vector>

namespace ohmdem::post {

struct BearingGeometry {
  std::string name;              // "6208", "6205" or "custom"
  int nb = 0;                    // number of balls
  double db = 0;                 // ball diameter (m)
  double dp = 0;                 // pitch diameter (m)
  double contact_angle_deg = 0;  // contact angle beta (degrees)
};

// Presets: SKF 6208 (the paper: Nb 13, Db 12.6 mm, D = (73.2 + 48)/2 = 60.6 mm) and SKF 6205
// (CWRU drive end: Nb 9, d 7.940 mm, D 39.04 mm); both with contact angle 0.
BearingGeometry bearing_preset(const std::string &name);
std::vector<std::string> bearing_preset_names();
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
