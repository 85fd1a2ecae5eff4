# The coupled yield scheme's excess past the surface while flowing, against the time step
# (scripts/coupled-yield-report.sh; data: case engine dt u_min u_mean u_max).
set terminal svg size 720,440 font "sans,13" background "#ffffff"
set output output
set logscale xy
set format y "10^{%L}"
set xlabel "time step dt [s]"
set ylabel "U - 1 of the loads while the joint flows"
set key top left
set grid
set title "Diagonal bending at 1.2 x the onset: the rows lag the turning load by one step (first order in dt)"
plot data using ($3):(strcol(1) eq "diagonal_bending" && strcol(2) eq "bullet" ? $6 - 1 : NaN) with points pt 7 ps 1.3 title "max, bullet", \
     data using ($3):(strcol(1) eq "diagonal_bending" && strcol(2) eq "ode" ? $6 - 1 : NaN) with points pt 6 ps 1.3 title "max, ode", \
     data using ($3):(strcol(1) eq "diagonal_bending" && strcol(2) eq "bullet" ? $5 - 1 : NaN) with points pt 5 ps 1.3 title "mean, bullet", \
     data using ($3):(strcol(1) eq "diagonal_bending" && strcol(2) eq "ode" ? $5 - 1 : NaN) with points pt 4 ps 1.3 title "mean, ode"
