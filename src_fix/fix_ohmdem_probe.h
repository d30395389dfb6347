#ifdef FIX_CLASS
FixStyle(ohmdem/probe,FixOhmdemProbe)
#else
#ifndef LMP_FIX_OHMDEM_PROBE_H
#define LMP_FIX_OHMDEM_PROBE_H
#include "fix.h"
namespace LAMMPS_NS {
class FixOhmdemProbe : public Fix {
 public:
  FixOhmdemProbe(class LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {}
  int setmask() override { return 0; }
};
}
#endif
#endif
