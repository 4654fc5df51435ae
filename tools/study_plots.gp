# study_plots.gp: the study's figures from the data files shadowlab study derives from
# study.csv (docs/accuracy.md). Run by `shadowlab study`; by hand:
#   gnuplot -e "dir='OUT/plots'; names='msm4 vsm'; title='classic'" tools/study_plots.gp
# Each DIR/plots/tech_<i>.dat: frame/copy ratio, truth RMSE, map bytes, label (one config per
# line); techfront_<i>.dat: that technique's own Pareto-optimal configs (its line);
# front.dat / front_bytes.dat: the Pareto front over all techniques.
if (!exists("dir")) dir = "plots"
if (!exists("names")) names = ""
if (!exists("title")) title = ""
if (!exists("out")) out = dir . "/../pareto"  # the time plot; the bytes plot adds "_bytes"
n = words(names)

set logscale xy
set termoption noenhanced  # scene names hold underscores (contact_hardening), not subscripts
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top
set ylabel "RMSE of G against the ray-traced truth"
set pointsize 1.1
# One marker shape and one colour per technique, in the technique table's order.
pt(i) = word("5 7 9 11 13 4 6 8 10 12 14 1 2 3", (i - 1) % 14 + 1) + 0
lc(i) = word("#1b9e77 #d95f02 #7570b3 #e7298a #66a61e #e6ab02 #a6761d #666666 #1f78b4 #b2df8a #fb9a99 #cab2d6", (i - 1) % 12 + 1)

do for [kind in "time bytes"] {
    if (kind eq "time") {
        set xlabel "frame cost / copy-pass cost (CPU time of all threads, minimum over repeats)"
        xcol = 1; front = dir . "/front.dat"; file = out
        set title title . ": error against time"
    } else {
        set xlabel "shadow-map bytes"
        xcol = 3; front = dir . "/front_bytes.dat"; file = out . "_bytes"
        set title title . ": error against memory"
    }
    do for [term in "svg pngcairo"] {
        if (term eq "svg") { set terminal svg size 900,560 dynamic font "sans,12"; set output file . ".svg" }
        else { set terminal pngcairo size 900,560 font "sans,10"; set output file . ".png" }
        plot for [i=1:n] sprintf("%s/tech_%d.dat", dir, i) using xcol:2 \
                 with points pt pt(i) lc rgb lc(i) title word(names, i), \
             for [i=1:n] sprintf("%s/%s_%d.dat", dir, (kind eq "time" ? "techfront" : "techfront_bytes"), i) \
                 using xcol:2 with lines lw 1.2 lc rgb lc(i) notitle, \
             front using xcol:2 with steps lw 2.5 lc rgb "black" title "Pareto front"
        unset output
    }
}
