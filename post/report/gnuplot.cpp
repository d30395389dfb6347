// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/gnuplot.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/pending_file.h"

namespace ohmdem::post {

namespace {

bool executable(const std::string &p)
{
  return !p.empty() && ::access(p.c_str(), X_OK) == 0;
}

bool is_control(unsigned char c)
{
  return c < 0x20 || c == 0x7f;
}

// The text with each control character written visibly (\n, \r, \t, \xHH): a newline in a
// gnuplot script ends the command, and what follows it would run as a command of its own.
std::string visible(const std::string &s)
{
  std::string v;
  for (unsigned char c : s) {
    if (!is_control(c)) {
      v += static_cast<char>(c);
    } else if (c == '\n' || c == '\r' || c == '\t') {
      v += c == '\n' ? "\\n" : c == '\r' ? "\\r" : "\\t";
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      v += buf;
    }
  }
  return v;
}

// A gnuplot string literal in single quotes (no backquote substitution, no escapes: the quote
// itself is doubled) of a text to show (titles, labels, legends): control characters shown as
// visible escapes, so that no text (a title, a run folder's name, a column's) ends the line.
std::string quote(const std::string &s)
{
  std::string q = "'";
  for (char c : visible(s)) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// A file name in a gnuplot script: a control character cannot be written in a single-quoted
// literal (it would end the line) and escaping it would name another file, so it is refused.
std::string quote_path(const std::string &path, const std::string &what)
{
  for (unsigned char c : path)
    if (is_control(c))
      throw Error("cannot plot: " + what + " '" + visible(path) +
                  "' holds a control character in its name (gnuplot cannot be given it)");
  return quote(path);
}

class TempDir {
 public:
  TempDir()
  {
    const char *base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/ohmdem-post-XXXXXX";
    std::vector<char> buf(tmpl.begin(), tmpl.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data()))
      throw Error(std::string("cannot create a temporary directory: ") + std::strerror(errno));
    path_ = buf.data();
  }
  ~TempDir()
  {
    for (const auto &f : files_) ::unlink(f.c_str());
    ::rmdir(path_.c_str());
  }
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  std::string file(const std::string &name)
  {
    files_.push_back(path_ + "/" + name);
    return files_.back();
  }

 private:
  std::string path_;
  std::vector<std::string> files_;
};

// The image as "x y z" rows, one blank line between x columns (gnuplot grid data).
void write_image(const PlotImage &im, const std::string &path)
{
  std::ofstream out(path);
  out.precision(9);
  const std::size_t nx = im.x.size(), ny = im.y.size();
  if (im.z.size() != nx * ny)
    throw Error("plot: image of " + std::to_string(im.z.size()) + " values for a " +
                std::to_string(nx) + " x " + std::to_string(ny) + " grid");
  for (std::size_t ix = 0; ix < nx; ++ix) {
    for (std::size_t iy = 0; iy < ny; ++iy)
      out << im.x[ix] << ' ' << im.y[iy] << ' ' << im.z[iy * nx + ix] << '\n';
    out << '\n';
  }
  out.close();
  if (!out) throw Error("cannot write plot data to " + path);
}

}  // namespace

std::vector<int> marker_label_rows(const std::vector<PlotMarker> &markers, double xmin, double xmax,
                                   double width_px)
{
  constexpr double kLabelWidthPx = 14;  // a rotated 8-point label and a gap
  std::vector<std::size_t> order(markers.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return markers[a].x < markers[b].x; });
  std::vector<int> rows(markers.size(), 0);
  std::vector<double> last_px;  // per row, the x (px) of its last label
  const double scale = xmax > xmin ? width_px / (xmax - xmin) : 0;
  for (std::size_t i : order) {
    const double px = (markers[i].x - xmin) * scale;
    std::size_t r = 0;
    while (r < last_px.size() && px - last_px[r] < kLabelWidthPx) ++r;
    if (r == last_px.size()) last_px.push_back(px);
    last_px[r] = px;
    rows[i] = static_cast<int>(r);
  }
  return rows;
}

MarkerLabelLayout marker_label_layout(const std::vector<PlotMarker> &markers, double xmin,
                                      double xmax, int width, int height)
{
  MarkerLabelLayout l;
  const std::vector<int> rows = marker_label_rows(markers, xmin, xmax, 0.85 * width);
  std::size_t longest = 0;
  int nrows = 0;
  for (std::size_t i = 0; i < markers.size(); ++i) {
    longest = std::max(longest, markers[i].label.size());
    nrows = std::max(nrows, rows[i] + 1);
  }
  const double row_px = longest * kMarkerCharPx + kMarkerGapPx;
  const double top_px = kTitlePx + nrows * row_px;
  l.graph_top = 1 - top_px / height;
  for (int r : rows)
    l.label_bottom.push_back(l.graph_top + (kMarkerGapPx / 2 + r * row_px) / height);
  l.row_height = row_px / height;
  return l;
}

std::string y_tick_format(double lo, double hi)
{
  if (!(std::isfinite(lo) && std::isfinite(hi) && hi > lo)) return "";
  // ticks at most a tenth of the span apart; %g prints 6 significant digits
  const double magnitude = std::max(std::fabs(lo), std::fabs(hi));
  const int digits = static_cast<int>(std::ceil(std::log10(magnitude / ((hi - lo) / 10)))) + 1;
  if (digits <= 6) return "";
  return "%." + std::to_string(std::min(digits, 15)) + "g";
}

std::string find_gnuplot()
{
  if (const char *env = std::getenv("OHMDEM_GNUPLOT")) return executable(env) ? env : "";
  const char *path = std::getenv("PATH");
  std::stringstream ss(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const std::string p = (dir.empty() ? "." : dir) + "/gnuplot";
    if (executable(p)) return p;
  }
  return "";
}

void decimate_minmax(const std::vector<double> &x, const std::vector<double> &y,
                     std::size_t max_points, std::vector<double> &xo, std::vector<double> &yo)
{
  xo.clear();
  yo.clear();
  const std::size_t n = std::min(x.size(), y.size());
  if (n <= max_points || max_points < 4) {
    xo.assign(x.begin(), x.begin() + static_cast<long>(n));
    yo.assign(y.begin(), y.begin() + static_cast<long>(n));
    return;
  }
  const std::size_t buckets = max_points / 2;
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t i0 = b * n / buckets, i1 = (b + 1) * n / buckets;
    std::size_t lo = i0, hi = i0;
    for (std::size_t i = i0; i < i1; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    const std::size_t a = std::min(lo, hi), c = std::max(lo, hi);
    xo.push_back(x[a]);
    yo.push_back(y[a]);
    if (c != a) {
      xo.push_back(x[c]);
      yo.push_back(y[c]);
    }
  }
}

void render_png(const Figure &fig, const std::string &png_path)
{
  const std::string gp = find_gnuplot();
  if (gp.empty())
    throw Error(
        "plot needs gnuplot (Debian package gnuplot-nox); none found in PATH "
        "(or set OHMDEM_GNUPLOT)");
  if (fig.series.empty() && fig.image.empty()) throw Error("plot: nothing to draw");
  quote_path(png_path, "the image file");  // refused before anything is created
  TempDir dir;
  PendingFile png(png_path);
  std::ostringstream script;
  script.precision(17);
  script << "set terminal pngcairo noenhanced size " << fig.width << "," << fig.height
         << " font 'Sans,10'\n"
         << "set output " << quote_path(png.path(), "the image") << "\n"
         << "set title " << quote(fig.title) << "\n"
         << "set xlabel " << quote(fig.xlabel) << "\n"
         << "set ylabel " << quote(fig.ylabel) << "\n"
         << "set grid lc rgb '#dddddd'\nset key below\n";
  if (fig.logy) script << "set logscale y\nset format y '%g'\n";
  // a bound as gnuplot reads it: all its digits (a microvolt range is no 0.000000), or *
  auto bound = [](double v) {
    std::ostringstream b;
    b.precision(17);
    if (std::isfinite(v))
      b << v;
    else
      b << '*';
    return b.str();
  };
  if (std::isfinite(fig.xmin) || std::isfinite(fig.xmax))
    script << "set xrange [" << bound(fig.xmin) << ":" << bound(fig.xmax) << "]\n";
  // A linear axis whose values differ far less than their size (a healthy R varying by 1e-7
  // of its mean) gets the digits that tell its ticks apart.
  if (!fig.logy && fig.image.empty()) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto &s : fig.series)
      for (double y : s.y)
        if (std::isfinite(y)) lo = std::min(lo, y), hi = std::max(hi, y);
    if (std::isfinite(fig.ymin)) lo = fig.ymin;
    if (std::isfinite(fig.ymax)) hi = fig.ymax;
    const std::string format = y_tick_format(lo, hi);
    if (!format.empty()) script << "set format y " << quote(format) << "\n";
  }
  int tag = 1;
  // The markers' labels stand above the graph, each centred on its line: in rows (close
  // markers in different rows), each row a label's length high, so no label crosses a line,
  // the data or another label. The x range: the figure's, else the markers' and the data's.
  double x0 = fig.xmin, x1 = fig.xmax;
  for (const auto &m : fig.markers) {
    if (!std::isfinite(fig.xmin)) x0 = std::isfinite(x0) ? std::min(x0, m.x) : m.x;
    if (!std::isfinite(fig.xmax)) x1 = std::isfinite(x1) ? std::max(x1, m.x) : m.x;
  }
  for (const auto &s : fig.series)
    for (double x : s.x) {
      if (!std::isfinite(fig.xmin) && x < x0) x0 = x;
      if (!std::isfinite(fig.xmax) && x > x1) x1 = x;
    }
  std::vector<PlotMarker> shown;
  for (const auto &m : fig.markers)
    if (m.x >= x0 && m.x <= x1) shown.push_back(m);
  if (!shown.empty()) {
    const MarkerLabelLayout layout = marker_label_layout(shown, x0, x1, fig.width, fig.height);
    // the title above the labels, at the top of the image
    script << "set tmargin at screen " << layout.graph_top << "\nunset title\n"
           << "set label " << tag++ << " " << quote(fig.title) << " at screen 0.5, screen "
           << 1 - kTitlePx / 2 / fig.height << " center\n";
    for (std::size_t k = 0; k < shown.size(); ++k) {
      const PlotMarker &m = shown[k];
      script << "set arrow " << tag << " from " << m.x << ", graph 0 to " << m.x
             << ", graph 1 nohead dt 2 lw 1 lc rgb " << quote(m.color) << "\n"
             << "set label " << tag << " " << quote(m.label) << " at first " << m.x << ", screen "
             << layout.label_bottom[k] << " rotate by 90 left tc rgb " << quote(m.color)
             << " font 'Sans," << kMarkerFontPt << "'\n";
      ++tag;
    }
  }
  if (!fig.image.empty())
    script << "set cblabel " << quote(fig.image.zlabel) << "\nset palette rgb 33,13,10\n";
  if (std::isfinite(fig.ymin) || std::isfinite(fig.ymax))
    script << "set yrange [" << bound(fig.ymin) << ":" << bound(fig.ymax) << "]\n";
  script << "plot ";
  if (!fig.image.empty()) {
    const std::string data = dir.file("image.dat");
    write_image(fig.image, data);
    script << quote_path(data, "the data file") << " using 1:2:3 with image notitle"
           << (fig.series.empty() ? "" : ", ");
  }
  for (std::size_t k = 0; k < fig.series.size(); ++k) {
    const PlotSeries &s = fig.series[k];
    const std::string data = dir.file("series" + std::to_string(k) + ".dat");
    std::ofstream out(data);
    out.precision(12);
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      if (fig.logy && !(s.y[i] > 0)) continue;
      out << s.x[i] << ' ' << s.y[i] << '\n';
    }
    out.close();
    if (!out) throw Error("cannot write plot data to " + data);
    script << (k ? ", " : "") << quote_path(data, "the data file") << " using 1:2 with " << s.style
           << " lw 1.2 title " << quote(s.title);
  }
  script << "\n";
  const std::string script_path = dir.file("figure.gp");
  const std::string log_path = dir.file("gnuplot.log");
  {
    std::ofstream gp_script(script_path);
    gp_script << script.str();
    gp_script.close();
    if (!gp_script) throw Error("cannot write the gnuplot script " + script_path);
  }
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(std::string("cannot start gnuplot: ") + std::strerror(errno));
  if (pid == 0) {
    std::FILE *log = std::fopen(log_path.c_str(), "w");
    if (log) {
      ::dup2(::fileno(log), 1);
      ::dup2(::fileno(log), 2);
    }
    ::execl(gp.c_str(), gp.c_str(), script_path.c_str(), static_cast<char *>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::ifstream logf(log_path);
  std::stringstream msg;
  msg << logf.rdbuf();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error("gnuplot failed writing '" + png_path + "': " + msg.str());
  struct stat st {};
  if (!png.in_place() && (::stat(png.path().c_str(), &st) != 0 || st.st_size == 0))
    throw Error("gnuplot wrote no image to '" + png_path + "': " + msg.str());
  const std::string why = png.commit();
  if (!why.empty()) throw Error("cannot write '" + png_path + "': " + why);
}

}  // namespace ohmdem::post
