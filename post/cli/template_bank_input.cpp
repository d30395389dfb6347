// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/template_bank_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "bearing/bearing.h"
#include "core/error.h"
#include "core/pending_file.h"
#include "dsp/butterworth.h"

namespace ohmdem::post::cli {

namespace {

const char *const kForm =
    "'# KEY: VALUE' header lines (bearing, defect, load, sampling rate (Hz), lowpass, bin (s), "
    "model error, and for a bank with several angles angle error (deg)), then lines 'SIZE_DEG "
    "ANGLE_DEG N Y_1..Y_N SE_1..SE_N' (studies/template_bank.py writes it)";

[[noreturn]] void bad(const std::string &path, const std::string &what)
{
  throw Error("diagnose: --template-bank " + path + ": " + what + "; expected " + kForm);
}

std::string trim(const std::string &s)
{
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// "Butterworth order 4, cut-off 8000 Hz (-3 dB), 2 sections at ..." -> up to "(-3 dB)"
std::string filter_part(const std::string &v)
{
  const auto k = v.find(" sections at");
  if (k == std::string::npos) return trim(v);
  const auto comma = v.rfind(',', k);
  return trim(comma == std::string::npos ? v : v.substr(0, comma));
}

double number(const std::string &path, const std::string &key, const std::string &v)
{
  std::istringstream in(v);
  double x = 0;
  if (!(in >> x) || !std::isfinite(x)) bad(path, "'" + key + "' is not a number ('" + v + "')");
  return x;
}

}  // namespace

bool same_geometry(const BearingGeometry &a, const BearingGeometry &b)
{
  // equal to the last digit a run.json or a catalog file prints (17 significant digits round
  // trip a double; 1e-12 leaves the last bits of a sum such as (Dext + Dinn)/2)
  const auto same = [](double x, double y) {
    return std::fabs(x - y) <= 1e-12 * std::max(std::fabs(x), std::fabs(y));
  };
  return a.nb == b.nb && same(a.db, b.db) && same(a.dp, b.dp) &&
         same(a.contact_angle_deg, b.contact_angle_deg);
}

std::string geometry_text(const BearingGeometry &g)
{
  return std::to_string(g.nb) + " balls of " + format_number(g.db * 1e3, 10) + " mm on " +
         format_number(g.dp * 1e3, 10) + " mm, contact angle " +
         format_number(g.contact_angle_deg, 10) + " deg";
}

BankFile read_template_bank(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw Error("diagnose: --template-bank " + path + ": cannot open the file");
  BankFile b;
  bool has_bin = false;
  std::string line;
  while (std::getline(in, line)) {
    if (trim(line).empty()) continue;
    if (line[0] == '#') {
      const auto c = line.find(':');
      if (c == std::string::npos) continue;
      const std::string key = trim(line.substr(1, c - 1)), v = trim(line.substr(c + 1));
      if (key == "bearing") b.bearing = v;
      if (key == "defect") b.defect = v;
      if (key == "load") b.load = v;
      if (key == "geometry") {
        std::istringstream gs(v);
        BearingGeometry g;
        double dext = 0, dinn = 0;
        if (!(gs >> g.nb >> g.db >> dext >> dinn) || g.nb < 1 || !(g.db > 0) || !(dext > dinn))
          bad(path, "the geometry must be 'NB DB DEXT DINN' (m)");
        g.name = "custom";
        g.dp = (dext + dinn) / 2;
        b.geometry = g;
      }
      if (key == "coverage" && v.rfind("not measured", 0) == 0) b.bank.coverage_measured = false;
      else if (key == "coverage") b.bank.coverage_note = v;
      if (key == "lowpass") b.lowpass = filter_part(v);
      if (key == "sampling rate (Hz)") b.rate = number(path, key, v);
      if (key == "fold period") {
        if (v != "grid" && v != "fine") bad(path, "the fold period must be grid or fine");
        b.fine_fold_period = v == "fine";
      }
      if (key == "bin (s)") b.bank.bin_s = number(path, key, v), has_bin = true;
      if (key == "model error") {
        b.bank.model_error = number(path, key, v);
        if (!(b.bank.model_error >= 0 && b.bank.model_error < 1))
          bad(path, "the model error must lie in [0, 1)");
      }
      if (key == "angle error (deg)") {
        b.bank.angle_error_deg = number(path, key, v);
        if (!(b.bank.angle_error_deg >= 0 && b.bank.angle_error_deg < 180))
          bad(path, "the angle error must lie in [0, 180) deg");
      }
      continue;
    }
    std::istringstream ls(line);
    PulseTemplate t;
    double n = 0;
    if (!(ls >> t.size_deg >> t.angle_deg >> n) || !(t.size_deg > 0) ||
        !std::isfinite(t.angle_deg) || !(n >= 8 && n < 1e6 && n == std::floor(n)))
      bad(path, "a template line must start 'SIZE_DEG ANGLE_DEG N' (size > 0, N >= 8 bins), got '" +
                    line.substr(0, 60) + "'");
    const auto bins = static_cast<std::size_t>(n);
    t.y.resize(bins);
    t.se.resize(bins);
    for (double &v : t.y)
      if (!(ls >> v) || !std::isfinite(v)) bad(path, "fewer than N finite values Y");
    for (double &v : t.se)
      if (!(ls >> v) || !std::isfinite(v) || !(v > 0)) bad(path, "fewer than N errors SE > 0");
    std::string extra;
    if (ls >> extra) bad(path, "more than 2 N values after 'SIZE_DEG ANGLE_DEG N'");
    b.bank.templates.push_back(std::move(t));
  }
  if (b.bearing.empty() || b.defect.empty() || !(b.rate > 0) || !has_bin || !(b.bank.bin_s > 0))
    bad(path,
        "the header must give the bearing, the defect, the sampling rate (Hz) and the bin (s)");
  if (b.defect != "inner" && b.defect != "outer") bad(path, "the defect must be inner or outer");
  std::vector<double> sizes, angles;
  try {
    bank_grid(b.bank, sizes, angles);
  } catch (const std::invalid_argument &e) {
    bad(path, e.what());
  }
  return b;
}

std::string record_lowpass(const std::string &record_path)
{
  std::ifstream in(record_path);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#')
    if (line.rfind("# lowpass:", 0) == 0) return filter_part(line.substr(10));
  return "";
}

std::optional<RecordFilter> record_filter(const std::string &record_path)
{
  std::ifstream in(record_path);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    if (line.rfind("# lowpass:", 0) != 0) continue;
    int order = 0;
    double fc = 0, fs = 0;
    const std::string v = line.substr(10);
    const auto cut = v.find("cut-off"), at = v.find("sections at");
    if (std::sscanf(v.c_str(), " Butterworth order %d", &order) != 1 || cut == std::string::npos ||
        at == std::string::npos || std::sscanf(v.c_str() + cut, "cut-off %lf", &fc) != 1 ||
        std::sscanf(v.c_str() + at, "sections at %lf", &fs) != 1)
      return std::nullopt;
    if (order < 1 || order > kMaxButterworthOrder || !(fc > 0 && fc < fs / 2)) return std::nullopt;
    return RecordFilter{butterworth_lowpass(order, fc, fs), fs};
  }
  return std::nullopt;
}

void check_bank(const BankFile &b, const Signal &s, const std::string &record_path,
                const BearingGeometry *bearing, const std::string &defect,
                const std::string &load)
{
  const std::string head = "diagnose: --template-bank: the bank was made ";
  if (std::fabs(b.rate / s.rate - 1) > 1e-6)
    throw Error(head + "at " + format_number(b.rate, 10) + " Hz, the record is sampled at " +
                format_number(s.rate, 10) +
                " Hz: give a bank made through the record's own chain (studies/template_bank.py "
                "--rates)");
  if (std::fabs(b.bank.bin_s * s.rate * kTemplateOversample - 1) > 1e-6)
    throw Error(head + "with bins of " + format_number(b.bank.bin_s, 6) + " s, expected 1/(" +
                std::to_string(kTemplateOversample) + " x rate)");
  const std::string lp = record_lowpass(record_path);
  if (!lp.empty() && !b.lowpass.empty() && lp != b.lowpass)
    throw Error(head + "through the anti-alias filter '" + b.lowpass + "', the record through '" +
                lp + "': give a bank made through the record's own chain");
  if (bearing) {
    // by value, never by name: a run.json saying "custom" whose geometry is the catalog
    // entry's is that bearing, and a catalog name with other values is not
    BearingGeometry of_bank;
    try {
      of_bank = b.geometry ? *b.geometry : catalog_entry(default_catalog_dir(), b.bearing).geometry();
    } catch (const Error &e) {
      throw Error(head + "for the bearing " + b.bearing + ", whose geometry the catalog does not "
                  "give (" + e.what() + ")");
    }
    if (!same_geometry(of_bank, *bearing))
      throw Error(head + "for the bearing " + b.bearing + " (" + geometry_text(of_bank) +
                  "), the record's is " + geometry_text(*bearing) + " (" + bearing->name + ")");
  }
  if (!defect.empty() && b.defect != defect)
    throw Error(head + "for an " + b.defect + " defect, the one sized is " + defect +
                " (identified, or --assume-defect)");
  if (!load.empty() && !b.load.empty() && b.load != load)
    throw Error(head + "under the " + b.load + " load, the record's is " + load + " (--load)");
}

void write_fold(const std::string &path, const FoldedPulse &p, const std::string &record_path)
{
  if (!p.valid) throw Error("diagnose: --pulse-fold-out: no fold of the record: " + p.note);
  std::unique_ptr<PendingStream> file;  // renamed onto `path` when whole
  try {
    file = std::make_unique<PendingStream>(path);
  } catch (const Error &e) {
    throw Error(std::string("diagnose: --pulse-fold-out: ") + e.what());
  }
  std::ostream &out = file->stream();
  out.precision(9);
  out << "# the record's pulse fold (diagnose --pulse-fold-out): relative to the level\n"
      << "# record: " << record_path << "\n"
      << "# lowpass: " << record_lowpass(record_path) << "\n"
      << "# bin (s): " << p.bin_s << "\n"
      << "# period (s): " << p.period_s << "\n"
      << "# fold period: " << (p.how == FoldPeriod::fine ? "fine" : "grid") << "\n"
      << "# passes: " << p.passes << "\n"
      << "# bins no pass fell in: " << p.empty << "\n"
      << "# Y SE\n";
  for (std::size_t j = 0; j < p.y.size(); ++j) out << p.y[j] << ' ' << p.se[j] << '\n';
  const std::string why = file->finish();
  if (!why.empty())
    throw Error("diagnose: --pulse-fold-out " + path + ": cannot write the file: " + why);
}

}  // namespace ohmdem::post::cli
