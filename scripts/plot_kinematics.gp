# Cage speed and mean ball loads of a bearing run (signal.txt of in.bearing).
#   gnuplot -e "sig='out/signal.txt'; png='out.png'" plot_kinematics.gp
set terminal pngcairo size 1000,700 font ",11"
set output png
set multiplot layout 2,1 title "SKF 6208, inner ring 500 rad/s: sliding phase, then rolling"
set xlabel "time (s)"
set ylabel "cage speed (rad/s)"
ftf = 250.0*(1 - 12.6/60.6)
set key bottom right
plot sig using 1:2 with lines lw 2 title "cage (simulated)", \
     ftf with lines dt 2 lc rgb "black" title sprintf("2{/Symbol p}FTF = %.2f rad/s", ftf)
set ylabel "mean ball load (N)"
set key top right
plot sig using 1:3 with lines lw 2 title "inner race", \
     sig using 1:4 with lines lw 2 title "outer race"
unset multiplot
