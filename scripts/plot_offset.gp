# A column of a bearing run as its offset from its mean over [t0, t1]: for a healthy run, whose
# R varies by parts per million, an axis of plain offsets (micro-ohm) instead of a zoom into
# 1.38380, 1.38380, ... tick labels. Columns are read by name from the signal's '#' header.
#   gnuplot -e "sig='out/signal.txt'; png='dR.png'; name='healthy'; t0=0.03; t1=0.04" plot_offset.gp
#   (ycol='R', yscale=1e6, yunit='micro-ohm' by default; tablefile='t.txt': the points as text)
if (!exists("ycol")) ycol = "R"
if (!exists("yscale")) yscale = 1e6
if (!exists("yunit")) yunit = "micro-ohm"
set terminal pngcairo size 1000,500 font ",11"
set output png
header = system("head -1 '" . sig . "'")
col(n) = sum [i = 2:words(header)] (word(header, i) eq n ? i - 1 : 0)
c_time = col("time"); c_y = col(ycol)
if (c_time * c_y == 0) {
  print "ERROR: plot_offset.gp: " . sig . " lacks the column time or " . ycol
  exit status 1
}
inwin(t) = (t >= t0 && t <= t1)
stats sig using (inwin(column(c_time)) ? column(c_y) : NaN) nooutput name "Y"
y0 = Y_mean
# Variations below 1e-9 of the value are round-off of the solve, not physics: said in the title.
rel = (Y_max - Y_min) / abs(y0)
floor = rel < 1e-9 ? sprintf("\nnumerical floor: peak to peak %.2g of %s0, round-off, no event", rel, ycol) \
                   : sprintf("\npeak to peak %.2g of %s0", rel, ycol)
if (exists("tablefile")) { set table tablefile }
set title sprintf("%s: %s - %s0 over %g..%g s (%s0 = %.9g; peak to peak %.3g %s)", name, ycol, \
                  ycol, t0, t1, ycol, y0, (Y_max - Y_min) * yscale, yunit) . floor noenhanced
set xlabel "time (s)"
set ylabel sprintf("%s - %s0 (%s)", ycol, ycol, yunit) noenhanced
set format y "%.3g"
if (exists("tablefile")) { set format y "%.12g" }  # the table takes the axis format
set xrange [t0:t1]
plot sig using (inwin(column(c_time)) ? column(c_time) : NaN):(yscale * (column(c_y) - y0)) \
     with lines lw 1.5 notitle
