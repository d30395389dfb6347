// SPDX-License-Identifier: GPL-2.0-or-later
// Registers the ohmdem styles in LIGGGHTS' style tables (fixes, computes, commands).
//
// LIGGGHTS 3.8 has no plugin loader and keeps its style maps (Modify::fix_map,
// Modify::compute_map, Input::command_map) private or protected. Two mechanisms, both confined to
// this file:
//  1. Access to the maps through an explicit template instantiation of a
//     member pointer: access checking does not apply to the names in an explicit
//     instantiation ([temp.explicit]), so this is standard C++.
//  2. A start-up hook: `clear` destroys Modify and builds a new one, then calls
//     LAMMPS::post_create(), as the LAMMPS constructor does. libliggghts calls it through
//     the PLT, so the definition below (exported by the executable, -rdynamic) is the one
//     used; it runs LIGGGHTS' own post_create() (found with dlsym(RTLD_NEXT)) and then
//     registers our styles. LAMMPS::help() is hooked the same way to list our styles.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "compute.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "ohmdem_style_list.h"

using namespace LAMMPS_NS;

namespace {

using FixCreator = Fix *(*)(LAMMPS *, int, char **);
using ComputeCreator = Compute *(*)(LAMMPS *, int, int, char **);
using FixMap = std::map<std::string, FixCreator>;
using ComputeMap = std::map<std::string, ComputeCreator>;
using CommandCreator = void (*)(LAMMPS *, int, char **);
using CommandMap = std::map<std::string, CommandCreator>;

template <typename Tag, typename Tag::type Member>
struct PrivateAccess {
  friend typename Tag::type get(Tag) { return Member; }
};
struct FixMapTag {
  using type = FixMap *Modify::*;
  friend type get(FixMapTag);
};
struct ComputeMapTag {
  using type = ComputeMap *Modify::*;
  friend type get(ComputeMapTag);
};
struct CommandMapTag {
  using type = CommandMap *Input::*;
  friend type get(CommandMapTag);
};
template struct PrivateAccess<FixMapTag, &Modify::fix_map>;
template struct PrivateAccess<CommandMapTag, &Input::command_map>;
template struct PrivateAccess<ComputeMapTag, &Modify::compute_map>;

// LIGGGHTS' own creator idiom: the engine owns and deletes the object.
template <typename T>
Fix *make_fix(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
template <typename T>
void run_command(LAMMPS *lmp, int narg, char **arg)
{
  T command(lmp);
  command.command(narg, arg);
}
template <typename T>
Compute *make_compute(LAMMPS *lmp, int iarg, int narg, char **arg)
{
  return new T(lmp, iarg, narg, arg);
}

void register_styles(LAMMPS *lmp)
{
  FixMap &fixes = *(lmp->modify->*get(FixMapTag{}));
  ComputeMap &computes = *(lmp->modify->*get(ComputeMapTag{}));
  // Input (and its command map) outlives `clear`; registering again is harmless.
  CommandMap &commands = *(lmp->input->*get(CommandMapTag{}));
  (void)fixes;
  (void)computes;
  (void)commands;
#define FIX_CLASS
#define COMPUTE_CLASS
#define COMMAND_CLASS
#define FixStyle(key, Class) fixes[#key] = &make_fix<Class>;
#define ComputeStyle(key, Class) computes[#key] = &make_compute<Class>;
#define CommandStyle(key, Class) commands[#key] = &run_command<Class>;
#include "ohmdem_style_list.h"
#undef FixStyle
#undef ComputeStyle
#undef CommandStyle
}

void print_styles(FILE *out)
{
  std::fprintf(out, "* ohmdem styles (this executable's additions):\n");
#define FixStyle(key, Class) std::fprintf(out, "  fix %s\n", #key);
#define ComputeStyle(key, Class) std::fprintf(out, "  compute %s\n", #key);
#define CommandStyle(key, Class) std::fprintf(out, "  command %s\n", #key);
#include "ohmdem_style_list.h"
#undef FixStyle
#undef ComputeStyle
#undef CommandStyle
#undef FIX_CLASS
#undef COMPUTE_CLASS
#undef COMMAND_CLASS
  std::fprintf(out, "\n");
}

template <typename Fn>
Fn liggghts_original(const char *mangled)
{
  void *sym = dlsym(RTLD_NEXT, mangled);
  if (!sym) {
    std::fprintf(stderr, "ohmdem: cannot find %s in libliggghts (%s)\n", mangled, dlerror());
    std::abort();
  }
  return reinterpret_cast<Fn>(sym);
}

}  // namespace

// The hooks. Member functions of LAMMPS are called with `this` as first argument.
void LAMMPS::post_create()
{
  static const auto original =
      liggghts_original<void (*)(LAMMPS *)>("_ZN9LAMMPS_NS6LAMMPS11post_createEv");
  original(this);
  register_styles(this);
}

void LAMMPS::help()
{
  static const auto original = liggghts_original<void (*)(LAMMPS *)>("_ZN9LAMMPS_NS6LAMMPS4helpEv");
  original(this);
  print_styles(screen);
}
