# study_cost_plots.gp: where a frame's cost goes, from the data files shadowlab study derives
# from study.csv. Run by `shadowlab study`; by hand:
#   gnuplot -e "dir='OUT/plots'; out='OUT/kernel_cost'; kseries='pcf:gaussian msm4:sat'; kmap=1024; title='classic'" tools/study_cost_plots.gp
# kernel_<i>.dat: radius, frame/copy, filter passes/copy, lighting/copy (one technique and
# filter at map size kmap²): PCF's lighting grows with the kernel's area (r²), a separable
# Gaussian with its width (r), a SAT not at all. passes.dat: per technique, its shadow, filter
# and lighting passes over the copy pass, stacked (OUT/.../pass_cost.*).
if (!exists("dir")) dir = "plots"
if (!exists("kseries")) kseries = ""
if (!exists("kmap")) kmap = 1024
if (!exists("title")) title = ""
if (!exists("out")) out = dir . "/../kernel_cost"
if (!exists("bars")) bars = dir . "/../pass_cost"
set termoption noenhanced
set grid ytics lc rgb "#dddddd"
set key outside right top
lc(i) = word("#1b9e77 #d95f02 #7570b3 #e7298a #66a61e #e6ab02 #a6761d #666666 #1f78b4 #b2df8a #fb9a99 #cab2d6", (i - 1) % 12 + 1)
pt(i) = word("5 7 9 11 13 4 6 8 10 12 14 1 2 3", (i - 1) % 14 + 1) + 0
m = words(kseries)
do for [term in "svg pngcairo"] {
    if (term eq "svg") { set terminal svg size 1000,560 dynamic font "sans,12"; set output out . ".svg" }
    else { set terminal pngcairo size 1000,560 font "sans,10"; set output out . ".png" }
    set title sprintf("%s: frame cost against kernel radius (map %d²)", title, kmap)
    set logscale xy
    set autoscale xfix
    set offsets graph 0.03, graph 0.03, 0, 0
    set xtics 2 
    set xlabel "kernel radius r (Gaussian 2r+1 taps, SAT box r·√3 texels)"
    set ylabel "frame cost / copy-pass cost"
    if (m > 0) {
        plot for [i=1:m] sprintf("%s/kernel_%d.dat", dir, i) using 1:2 with linespoints \
                 pt pt(i) lc rgb lc(i) lw 1.5 title word(kseries, i)
    } else {
        set xrange [1:10]; set yrange [0.1:10]
        set label 1 "one radius per technique: no kernel axis (sweep --radii 1,2,4,...)" at graph 0.5, 0.5 center
        plot NaN notitle
        unset label 1; set autoscale
    }
    unset output
}
unset logscale
set offsets 0, 0, 0, 0
set autoscale x
set xtics autofreq
set style data histograms
set style histogram rowstacked
set style fill solid 0.8 border -1
set boxwidth 0.7
set xtics rotate by -35 left
set ylabel "cost / copy-pass cost (median)"
set xlabel ""
do for [term in "svg pngcairo"] {
    if (term eq "svg") { set terminal svg size 1000,560 dynamic font "sans,12"; set output bars . ".svg" }
    else { set terminal pngcairo size 1000,560 font "sans,10"; set output bars . ".png" }
    set title sprintf("%s: cost per pass (map %d², smallest kernel)", title, kmap)
    plot dir . "/passes.dat" using 2:xtic(1) title "shadow" lc rgb "#66a61e", \
         "" using 3 title "filter" lc rgb "#1f78b4", \
         "" using 4 title "lighting" lc rgb "#e6ab02"
    unset output
}
