# Cage speed and mean ball loads of a bearing run (signal.txt of in.bearing), columns read by
# their names in the signal's '#' header line (never by position: the layout grows).
#   gnuplot -e "sig='out/signal.txt'; png='out.png'" plot_kinematics.gp
#   gnuplot -e "sig=...; png=...; tablefile='t.txt'" plot_kinematics.gp   (the plotted points as
#   text, for tests/decks/demo_plot_tests.py)
set terminal pngcairo size 1000,700 font ",11"
set output png
header = system("head -1 '" . sig . "'")
# header word i names column i-1 (word 1 is the '#')
col(name) = sum [i = 2:words(header)] (word(header, i) eq name ? i - 1 : 0)
c_time = col("time"); c_cage = col("omega_cage")
c_in = col("fn_inner_mean"); c_out = col("fn_outer_mean")
if (c_time * c_cage * c_in * c_out == 0) {
  print "ERROR: plot_kinematics.gp: " . sig . " lacks a column of time omega_cage fn_inner_mean fn_outer_mean"
  exit status 1
}
if (exists("tablefile")) { set table tablefile }
# name='RUN': the run named in the title (the demo: healthy)
if (!exists("name")) name = sig
set multiplot layout 2,1 title sprintf("run %s: SKF 6208, inner ring 500 rad/s: sliding phase, then rolling", name) noenhanced
set xlabel "time (s)"
set ylabel "cage speed (rad/s)"
ftf = 250.0*(1 - 12.6/60.6)
set key bottom right
plot sig using c_time:c_cage with lines lw 2 title "cage (simulated)", \
     ftf with lines dt 2 lc rgb "black" title sprintf("2{/Symbol p}FTF = %.2f rad/s", ftf)
set ylabel "mean ball load (N)"
set key top right
plot sig using c_time:c_in with lines lw 2 title "inner race", \
     sig using c_time:c_out with lines lw 2 title "outer race"
unset multiplot
