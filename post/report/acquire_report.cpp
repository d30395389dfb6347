// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/acquire_report.h"

#include "core/text_scan.h"
#include "io/json.h"

namespace ohmdem::post {

namespace {

std::string line(const std::string &k, const std::string &v)
{
  return "# " + k + ": " + v + "\n";
}

}  // namespace

std::string acquisition_head(const std::string &version, const MetaList &input_meta)
{
  std::string text = "# ohmdem-post " + version + " acquire: what an instrument records\n";
  for (const auto &kv : input_meta)
    text +=
        "# " + (kv.first == "source" ? kv.first : "input " + kv.first) + ": " + kv.second + "\n";
  return text;
}

std::string acquisition_chain(const AcquireSettings &s, const Acquisition &q,
                              const AcquisitionContext &c)
{
  const Signal &y = q.signal;
  const double fs_in = c.input_rate;
  std::string m;
  m +=
      line("chain", "scale/offset -> anti-alias low-pass (input rate) -> sampling -> noise -> ADC");
  m += line("scale", format_number(s.scale, 10) + " (output = scale * input + offset)");
  m += line("offset", format_number(s.offset, 10));
  if (q.filter.empty())
    m += line("lowpass", "none");
  else
    m += line("lowpass", "Butterworth order " + std::to_string(s.order) + ", cut-off " +
                             format_number(s.lowpass) + " Hz (-3 dB), " +
                             std::to_string(q.filter.size()) + " sections at " +
                             format_number(fs_in, 10) + " Hz, " +
                             (s.steady_start ? "steady" : "zero") + " initial state");
  if (q.decimation == 1 && !c.rate_given)
    m += line("sampling", "the input's samples");
  else if (q.decimation > 0)
    m += line("sampling", "every k-th sample of the input, k = " + std::to_string(q.decimation));
  else
    m += line("sampling",
              "cubic (4-point Lagrange) interpolation at " + format_number(y.rate, 10) +
                  " Hz; error on a tone at f <= (3/128)(2 pi f/" + format_number(fs_in, 10) +
                  ")^4 of its amplitude (" +
                  format_number(
                      cubic_interpolation_error(s.lowpass > 0 ? s.lowpass : y.rate / 2, fs_in), 3) +
                  (s.lowpass > 0 ? " at the cut-off)" : " at the output Nyquist frequency)"));
  if (q.noise_sigma > 0)
    m += line("noise", "white Gaussian added to the samples, rms " +
                           format_number(q.noise_sigma, 10) + " (" +
                           (s.noise_density > 0 ? "density " + format_number(s.noise_density, 10) +
                                                      " per sqrt(Hz) over 0 to rate/2 = " +
                                                      format_number(y.rate / 2, 10) + " Hz"
                                                : std::string("{acquire.noise_rms}")) +
                           (c.input_referred ? ", input-referred x |scale|" : "") +
                           "), mt19937_64 + Box-Muller, seed " + std::to_string(s.seed));
  else
    m += line("noise", "none");
  if (s.bits > 0)
    m += line("adc", std::to_string(s.bits) + " bits, range " + format_number(s.lo, 10) + " to " +
                         format_number(s.hi, 10) + ", q = " + format_number(q.q, 10) +
                         ", mid-tread (levels LO + k q), clipped " + std::to_string(q.clipped) +
                         " of " + std::to_string(y.size()));
  else
    m += line("adc", "none");
  if (!c.unit.empty()) m += line("unit", c.unit);
  m += line("sampling rate (Hz)", format_number(y.rate, 10));
  m += line("samples", std::to_string(y.size()));
  m += line("duration (s)", format_number(y.duration()));
  return m;
}

std::string acquisition_table(const Signal &y, const std::string &name, const Signal *second,
                              const std::string &second_name, bool csv)
{
  const char sep = csv ? ',' : ' ';
  std::string text = (csv ? "time," : "# time ") + name;
  if (second) text += sep + second_name;
  text += '\n';
  for (std::size_t i = 0; i < y.size(); ++i) {
    text += json_number(y.time(i));
    text += sep;
    text += json_number(y.x[i]);
    if (second) {
      text += sep;
      text += json_number(second->x[i]);
    }
    text += '\n';
  }
  return text;
}

}  // namespace ohmdem::post
