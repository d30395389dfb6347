// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command bearing_catalog (doc/command_bearing_catalog.md)

     bearing_catalog NAME [catalog DIR|auto] [prefix PREFIX]

   NAME and DIR may be v_VARIABLE: the variable's value, taken whole (the deck
   passes v_bearing, so that no value is split into words or substituted).

   Defines, as `include` of the entry did, an index variable for every line of
   the entry (Nb, Db, Dext, Dinn, Rcext, Rcinn: a value given with -var wins),
   and PREFIX + each name with the entry's own value, so that the deck can tell
   whether -var changed the geometry, and PREFIX + entry = the entry's name (an
   alias resolved). An entry without a pitch diameter or ball set that the
   simulation needs is refused, naming it (-var Dpw: races Dpw +- Db). NAME =
   custom: no file, the PREFIX copies are -1. Rank 0 reads the file, every rank
   defines the variables.
------------------------------------------------------------------------- */

#include "BEARING/command_bearing_catalog.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>

#include "catalog/bearing_catalog.h"
#include "comm.h"
#include "error.h"
#include "input.h"
#include "support/args.h"
#include "variable.h"

using namespace LAMMPS_NS;
namespace cat = ohmdem::catalog;

namespace {

const char *const kStyle = "bearing_catalog";
const char *const kGeometry[] = {"Nb", "Db", "Dext", "Dinn", "Rcext", "Rcinn"};

// The entry NAME of DIR (an alias resolved), or the error message for the deck's user.
std::string read_entry(const std::string &dir, const std::string &name, cat::CatalogEntry &entry)
{
  std::vector<std::string> names;
  std::string folder_error;
  try {
    names = cat::catalog_names(dir);
  } catch (const cat::CatalogError &e) {
    folder_error = std::string(e.what()) + ": give -var catalog DIR or set OHMDEM_CATALOG";
  }
  // The name first: it is refused as it is, whatever the folder holds.
  if (!cat::is_catalog_name(name))
    return "bearing '" + name +
           "' is not a catalog name (no path, no dot; letters, digits, '_' and '-' only). "
           "Known bearings in " +
           dir + ": " + cat::joined_names(names) + ", or custom";
  if (!folder_error.empty()) return folder_error;
  bool known = false;
  for (const auto &n : names) known = known || n == name;
  if (!known)
    return "bearing '" + name + "' is not in the catalog " + dir +
           ". Known bearings: " + cat::joined_names(names) +
           "; or -var bearing custom with -var Nb, Db, Dext, Dinn (and optionally Rcext, Rcinn)";
  try {
    entry = cat::read_entry(dir, name);
  } catch (const cat::CatalogError &e) {
    return e.what();
  }
  return "";
}

}  // namespace

BearingCatalog::BearingCatalog(LAMMPS *lmp) : Pointers(lmp) {}

void BearingCatalog::command(int narg, char **arg)
{
  if (narg < 1)
    error->all(FLERR, "bearing_catalog: expects a catalog name (or custom) as first argument");
  const std::string name = value_of(arg[0], "the catalog name");
  std::string dir = "auto", prefix = "catalog_";
  ohmdem::StyleArgs args(error, kStyle, narg, arg, 1);
  while (!args.done()) {
    const std::string key = args.word("", "");
    if (key == "catalog")
      dir = value_of(args.word("catalog", "a catalog folder or auto"), "the catalog folder");
    else if (key == "prefix")
      prefix = args.word("prefix", "a variable name prefix");
    else
      args.unknown(key.c_str(), "catalog, prefix");
  }
  if (dir == "auto") dir = cat::default_catalog_dir();

  // Rank 0 reads the entry and decides what to define; every rank defines the same. Each
  // variable travels as "=NAME" (the entry line: NAME and its copy), "+NAME" (derived: NAME
  // only), "@NAME" (a copy only, PREFIX + NAME).
  std::string message, line;
  Variables variables;
  if (comm->me == 0) {
    cat::CatalogEntry entry;
    if (name != "custom") message = read_entry(dir, name, entry);
    // the entry that runs, for run.json's "bearing" (first: an entry line cannot shadow it)
    variables.emplace_back("@entry", name == "custom" ? "custom" : entry.name);
    Variables given;
    for (const char *v : {"Nb", "Db", "Dext", "Dinn", "Dpw"})
      if (const char *value = input->variable->retrieve(const_cast<char *>(v)))
        given.emplace_back(v, value);
    if (message.empty()) {
      const cat::DeckGeometry deck =
          cat::deck_geometry_of(name == "custom" ? nullptr : &entry, given);
      message = deck.error;
      for (const auto &[var, value] : deck.define) variables.emplace_back("+" + var, value);
      for (const auto &[var, value] : deck.copies) variables.emplace_back("@" + var, value);
    }
    if (name == "custom") {
      for (const char *v : kGeometry) variables.emplace_back(std::string("@") + v, "-1");
      line = "bearing_catalog: bearing custom (dimensions from -var)\n";
    } else if (message.empty()) {
      for (const auto &[var, value] : entry.variables) variables.emplace_back("=" + var, value);
      line = "bearing_catalog: bearing " + name + " from " + entry.path + "\n";
      if (entry.name != name)
        line = "bearing_catalog: bearing " + name + " = " + entry.name + " from " + entry.path +
               " (the default of the name " + name +
               "; others: " + cat::joined_names(entry.others) + ")\n";
    }
  }
  broadcast(message, variables);
  if (!message.empty()) fail(message);
  for (const auto &[var, value] : variables) {
    const std::string v = var.substr(1);
    if (var[0] != '@') define_index(v, value);
    if (var[0] != '+') define_index(prefix + v, value);
  }
  if (comm->me == 0) {
    if (screen) std::fputs(line.c_str(), screen);
    if (logfile) std::fputs(line.c_str(), logfile);
  }
}

std::string BearingCatalog::value_of(const std::string &word, const char *what)
{
  if (word.compare(0, 2, "v_") != 0) return word;
  std::string variable = word.substr(2);
  const char *value = input->variable->retrieve(variable.data());
  if (!value) {
    const std::string msg =
        std::string(kStyle) + ": no variable '" + variable + "' (" + word + " gives " + what + ")";
    fail(msg);
  }
  return value;
}

void BearingCatalog::fail(const std::string &message)
{
  error->all(FLERR, message.c_str());
  std::abort();  // error->all does not return; this keeps the compiler informed
}

void BearingCatalog::broadcast(std::string &message, Variables &variables)
{
  // One text: the message, then name and value of each variable, one a line.
  std::string text;
  if (comm->me == 0) {
    text = message + "\n";
    for (const auto &[var, value] : variables) text += var + "\n" + value + "\n";
  }
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, 0, world);
  if (comm->me == 0) return;
  std::vector<std::string> lines;
  for (std::size_t start = 0, end; start < text.size(); start = end + 1) {
    end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
  }
  message = lines.empty() ? "" : lines[0];
  variables.clear();
  for (std::size_t i = 1; i + 1 < lines.size(); i += 2)
    variables.emplace_back(lines[i], lines[i + 1]);
}

void BearingCatalog::define_index(const std::string &name, const std::string &value)
{
  // As the line "variable NAME index VALUE": an index variable that exists (-var) is kept.
  std::string words[3] = {name, "index", value};
  char *argv[3] = {words[0].data(), words[1].data(), words[2].data()};
  input->variable->set(3, argv);
}
