// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/run_metadata.h"

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "io/json.h"

namespace ohmdem::post {

namespace {

std::optional<double> number(const Json &o, const std::string &key, const std::string &path)
{
  const Json *v = o.find(key);
  if (!v || v->is_null()) return std::nullopt;
  if (!v->is_number() || !std::isfinite(v->number()))
    throw Error(path + ": \"" + key + "\" must be a finite number");
  return v->number();
}

// A count (the number of balls): a whole number >= 1, never rounded (13.5 balls is no bearing).
std::optional<double> count(const Json &o, const std::string &key, const std::string &path)
{
  const std::optional<double> v = number(o, key, path);
  if (v && !(*v >= 1 && *v <= 1e9 && std::floor(*v) == *v))
    throw Error(path + ": \"" + key + "\" must be a whole number >= 1, got " + Json(*v).dump());
  return v;
}

std::optional<std::string> text(const Json &o, const std::string &key, const std::string &path)
{
  const Json *v = o.find(key);
  if (!v || v->is_null()) return std::nullopt;
  if (v->is_string()) return v->string();
  if (v->is_number()) return Json(v->number()).dump();  // "bearing": 6208 written as a number
  throw Error(path + ": \"" + key + "\" must be a string");
}

}  // namespace

RunMetadata read_run_metadata(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open metadata file '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  Json j = Json::parse(ss.str(), path);
  if (!j.is_object()) throw Error(path + ": metadata must be a JSON object");
  RunMetadata m;
  m.path = path;
  m.bearing = text(j, "bearing", path);
  m.defect = text(j, "defect", path);
  m.load = text(j, "load", path);
  if (m.load && *m.load == "shaft") {
    const std::optional<double> fr = number(j, "Fr", path);
    m.load = fr && *fr > 0.0 ? "radial" : "force";
  }
  m.omega_inner = number(j, "omega_inner", path);
  m.nb = count(j, "nb", path);
  m.db = number(j, "db", path);
  m.dp = number(j, "dp", path);
  m.catalog_name = text(j, "catalog_name", path);
  m.dext = number(j, "dext", path);
  m.dinn = number(j, "dinn", path);
  m.rc_ext = number(j, "rc_ext", path);
  m.rc_inn = number(j, "rc_inn", path);
  m.contact_angle = number(j, "contact_angle", path);
  m.dt = number(j, "dt", path);
  m.size_deg = number(j, "size_deg", path);
  m.t_sliding_end = number(j, "t_sliding_end", path);
  m.status = text(j, "status", path);
  // running: written before the run; a run killed outright (SIGKILL, an MPI abort) keeps it
  if (m.status && *m.status != "finished" && *m.status != "interrupted" && *m.status != "failed" &&
      *m.status != "running")
    throw Error(path + ": \"status\" must be \"running\", \"finished\", \"interrupted\" or " +
                "\"failed\", got \"" + *m.status + "\"");
  m.time_reached = number(j, "time_reached", path);
  return m;
}

std::string find_run_metadata(const std::string &signal_path)
{
  if (signal_path == "-") return "";
  const auto slash = signal_path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : signal_path.substr(0, slash);
  const std::string candidate = dir + "/run.json";
  struct stat st {};
  return ::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) ? candidate : "";
}

}  // namespace ohmdem::post
