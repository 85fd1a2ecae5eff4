# Error against run time, one panel per section (data: tools/cubature-report --plot-data).
set terminal svg size 1200,800 dynamic font "sans,11" background "white"
set output output
set logscale xy
set format y "1e%T"
set xlabel "time per section, meshing included [µs]"
set ylabel "worst relative error of N, Q, Mx, Mz, My"
set yrange [1e-17:10]
set grid
set key top right font ",9"
titles = "'paper square 10 mm' 'T 100x210 mm' 'I 310UB-type' '256-gon R 50 mm' 'strip 1:1000' 'hollow rectangle'"
set multiplot layout 2,3
do for [c=0:5] {
  set title word(titles, c + 1)
  if (c == 0) {
    set arrow 1 from graph 0, first 7.1e-5 to graph 1, first 7.1e-5 nohead dashtype 2 lc rgb "#888888"
    set label 1 "Octave dblquad (seed)" at graph 0.02, first 2e-4 textcolor rgb "#666666"
  } else { unset arrow 1; unset label 1 }
  plot data index (5*c+1) using 1:2 with linespoints pt 7 lc rgb "#1f77b4" title "adaptive, conforming", \
       data index (5*c+2) using 1:2 with linespoints pt 6 lc rgb "#9ecae1" title "adaptive, ignores kinks", \
       data index (5*c+3) using 1:2 with points pt 5 lc rgb "#d62728" title "fixed, conforming", \
       data index (5*c+4) using 1:2 with points pt 4 lc rgb "#ff9896" title "fixed, ignores kinks", \
       data index (5*c+0) using 1:2 with points pt 9 ps 2 lc rgb "#000000" title "exact route (error 0 at 1e-17)"
}
unset multiplot
