// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/model_cache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "bearing/bearing.h"
#include "core/error.h"
#include "core/pending_file.h"
#include "core/sampled_signal.h"
#include "io/json.h"

namespace ohmdem::post::cli {

namespace {

std::string hex64(std::uint64_t h)
{
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

std::uint64_t fnv1a(const std::string &s)
{
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return h;
}

// The record's header lines '# KEY: VALUE' (acquire's), up to its first data line.
std::map<std::string, std::string> header(const std::string &path)
{
  std::map<std::string, std::string> h;
  std::ifstream in(path);
  if (!in) throw Error("model: " + path + ": cannot open the record");
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    const auto c = line.find(": ");
    if (c != std::string::npos && c > 2) h[line.substr(2, c - 2)] = line.substr(c + 2);
  }
  return h;
}

std::string word_after(const std::string &text, const std::string &what)
{
  const auto k = text.find(what);
  if (k == std::string::npos) return "";
  std::istringstream in(text.substr(k + what.size()));
  std::string w;
  in >> w;
  while (!w.empty() && (w.back() == ',' || w.back() == ')')) w.pop_back();
  return w;
}

bool is_dir(const std::string &p)
{
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

void make_dirs(const std::string &p)
{
  for (std::size_t k = 1; k <= p.size(); ++k)
    if (k == p.size() || p[k] == '/') {
      const std::string d = p.substr(0, k);
      if (!is_dir(d) && ::mkdir(d.c_str(), 0755) != 0 && !is_dir(d))
        throw Error("model: cannot create the cache folder " + d +
                    " (set OHMDEM_CACHE to a writable folder)");
    }
}

}  // namespace

Scene record_scene(const std::string &record, const RunMetadata &meta, const std::string &defect,
                   const std::vector<double> &sizes, double length, int held_out)
{
  if (meta.path.empty())
    throw Error("model: the record's scene needs its run.json (--metadata FILE, or beside the "
                "record or its source)");
  std::ifstream jin(meta.path);
  std::stringstream js;
  js << jin.rdbuf();
  const Json j = Json::parse(js.str(), meta.path);
  if (const Json *m = j.find("model"); m && m->is_string() && m->string() == "3d")
    throw Error("model: " + meta.path +
                " is a model 3d run's: banks and curves are made of the planar scene (model 2d) "
                "only");
  std::map<std::string, std::string> v;  // the scene's values, canonical
  std::vector<std::string> deck;
  // run.json's key -> the deck's variable: the bearing by its values ("custom"), never its name
  const std::pair<const char *, const char *> keys[] = {
      {"nb", "Nb"},         {"db", "Db"},           {"dext", "Dext"},
      {"dinn", "Dinn"},     {"rc_ext", "Rcext"},    {"rc_inn", "Rcinn"},
      {"omega_inner", "omega"}, {"load", "load"},   {"F", "F"},
      {"I", "I"},           {"depth", "depth"},     {"cage_clearance", "cclear"},
      {"cage_mass", "mcage"}, {"ring_mass", "Mring"}, {"ring_damping", "Cring"},
      {"gamma", "gamma"},   {"area", "area"},       {"dt", "dt"},
      {"t_sliding_end", "tslide"}};
  for (const auto &[key, var] : keys) {
    const Json *x = j.find(key);
    if (!x || x->is_null()) {
      if (std::string(key) == "depth") continue;  // the deck's default pit (a user's record)
      throw Error("model: " + meta.path + " gives no '" + key +
                  "' (the scene's bearing, speed, load and chain are all needed)");
    }
    const std::string text = x->is_number() ? format_number(x->number(), 17) : x->string();
    v[key] = text;
    deck.insert(deck.end(), {"-var", var, text});
  }
  if (j.find("omega_start") && j.find("ramp") && j.find("ramp")->is_number() &&
      j.find("ramp")->number() != 0)
    throw Error("model: the record's run ramps its speed: a bank is made at a constant speed");
  const double tslide = std::atof(v["t_sliding_end"].c_str());
  deck.insert(deck.end(), {"-var", "bearing", "custom", "-var", "position", "90", "-var", "tend",
                          format_number(tslide + length, 10)});
  // the chain, as the record's header states it
  auto h = header(record);
  auto need = [&](const std::string &k) -> const std::string & {
    if (!h.count(k))
      throw Error("model: " + record + " has no '# " + k +
                  ":' line: the chain is read from the header acquire writes (acquire the record "
                  "with ohmdem-post acquire)");
    return h[k];
  };
  std::vector<std::string> acq{"--from", format_number(tslide, 10), "--scale",
                               word_after("x" + need("scale"), "x"), "--offset", need("offset")};
  const std::string &lp = need("lowpass");
  if (lp != "none")
    acq.insert(acq.end(), {"--lowpass", word_after(lp, "cut-off "), "--order", word_after(lp, "order ")});
  acq.insert(acq.end(), {"--rate", need("sampling rate (Hz)")});
  const std::string &noise = need("noise");
  if (noise != "none")
    // another draw of the same noise than the record's (its seed + 1000)
    acq.insert(acq.end(), {"--noise-density", word_after(noise, "(density "), "--seed",
                           std::to_string(std::atol(word_after(noise, "seed ").c_str()) + 1000)});
  const std::string &adc = need("adc");
  if (adc != "none")
    acq.insert(acq.end(), {"--bits", word_after(adc, ""), "--range", word_after(adc, "range "),
                           word_after(adc, " to ")});
  Scene s;
  s.rate = need("sampling rate (Hz)");
  std::string chain;  // the arguments as one line: part of the key
  for (const std::string &w : acq) chain += " " + w;
  v["chain"] = chain;
  v["defect"] = defect;
  std::string sz;
  for (double x : sizes) sz += (sz.empty() ? "" : ",") + format_number(x, 10);
  v["sizes_deg"] = sz;
  v["length_s"] = format_number(length, 10);
  v["held_out"] = std::to_string(held_out);
  for (const auto &[k, x] : v) s.text += k + " = " + x + "\n";
  s.key = hex64(fnv1a(s.text));
  s.deck_args = deck;
  s.acquire_args = acq;
  // the bank's own header: the geometry by value (template_bank_input.h reads it)
  return s;
}

std::string cache_dir()
{
  std::string d;
  if (const char *c = std::getenv("OHMDEM_CACHE"); c && *c)
    d = c;
  else if (const char *x = std::getenv("XDG_CACHE_HOME"); x && *x)
    d = std::string(x) + "/ohmdem";
  else if (const char *home = std::getenv("HOME"); home && *home)
    d = std::string(home) + "/.cache/ohmdem";
  else
    throw Error("model: no cache folder: set OHMDEM_CACHE (or XDG_CACHE_HOME or HOME)");
  make_dirs(d + "/banks");
  return d;
}

std::string cached_bank_path(const Scene &s)
{
  return cache_dir() + "/banks/bank_" + s.key + ".txt";
}

void write_bank_file(const std::string &path, const Scene &s, const std::string &lowpass,
                     const std::string &bin, const std::string &rows, double model_error,
                     const std::string &coverage)
{
  PendingStream f(path);
  std::ostream &out = f.stream();
  const auto value = [&](const std::string &k) {
    const auto a = s.text.find(k + " = ");
    return a == std::string::npos ? std::string()
                                  : s.text.substr(a + k.size() + 3,
                                                  s.text.find('\n', a) - a - k.size() - 3);
  };
  out << "# ohmdem-post pulse template bank (ohmdem-post model): the scene " << s.key << "\n"
      << "# bearing: custom\n"
      << "# geometry: " << value("nb") << " " << value("db") << " " << value("dext") << " "
      << value("dinn") << "\n"
      << "# defect: " << value("defect") << "\n# load: " << value("load") << "\n"
      << "# sampling rate (Hz): " << s.rate << "\n# lowpass: " << lowpass << "\n"
      << "# bin (s): " << bin << "\n"
      << "# model error: " << format_number(model_error, 6) << "\n# coverage: " << coverage
      << "\n";
  std::istringstream lines(s.text);
  for (std::string l; std::getline(lines, l);) out << "# scene: " << l << "\n";
  out << "# SIZE_DEG ANGLE_DEG N Y_1..Y_N SE_1..SE_N\n" << rows;
  const std::string why = f.finish();
  if (!why.empty()) throw Error("model: cannot write " + path + ": " + why);
}

const std::vector<double> &default_bank_sizes()
{
  static const std::vector<double> s{0.2,  0.25, 0.31, 0.39, 0.49, 0.61, 0.76,
                                     0.95, 1.19, 1.49, 1.86, 2.33, 2.91, 3.64};
  return s;
}

std::string self_executable()
{
  std::string exe(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1);
  return n > 0 ? exe.substr(0, static_cast<std::size_t>(n)) : "ohmdem-post";
}

std::string find_engine()
{
  const std::string self = self_executable();
  const std::string beside = self.substr(0, self.find_last_of('/') + 1) + "ohmdem";
  if (::access(beside.c_str(), X_OK) == 0) return beside;
  if (const char *path = std::getenv("PATH")) {
    std::istringstream in(path);
    for (std::string d; std::getline(in, d, ':');)
      if (!d.empty() && ::access((d + "/ohmdem").c_str(), X_OK) == 0) return d + "/ohmdem";
  }
  return "";
}

std::string default_deck()
{
  const std::string c = default_catalog_dir();  // .../inputs/bearings
  return c.substr(0, c.find_last_of('/')) + "/bearing_6208/in.bearing";
}

}  // namespace ohmdem::post::cli
