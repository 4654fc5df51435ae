# study_plots.gp: the study's Pareto figures from the data files shadowlab study derives from
# study.csv (docs/accuracy.md). Run by `shadowlab study`; by hand, e.g.:
#   gnuplot -e "dir='OUT/plots'; names='msm4 vsm'; title='classic'; sizes='256 1024'; \
#     kernels='none gaussian:r1'; kcolours='#000000 #9ecae1'; ymin=0.03; ymax=0.08" tools/study_plots.gp
# Each DIR/plots/tech_<i>.dat: frame/copy ratio, truth RMSE, map bytes, marker size (map size),
# colour (kernel, 0xRRGGBB), label (one config per line); techfront_<i>.dat: that technique's
# own Pareto-optimal configs (its line); front.dat / front_bytes.dat: the front over all.
# Markers: point type = technique, size = map size, colour = kernel (filter and radius).
if (!exists("dir")) dir = "plots"
if (!exists("names")) names = ""
if (!exists("title")) title = ""
if (!exists("sizes")) sizes = ""
if (!exists("kernels")) kernels = ""
if (!exists("kcolours")) kcolours = ""
if (!exists("out")) out = dir . "/../pareto"  # the time plot; the bytes plot adds "_bytes"
n = words(names)

set logscale xy
set termoption noenhanced  # scene names hold underscores (contact_hardening), not subscripts
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top
set ylabel "RMSE of G against the ray-traced truth"
# The y axis spans the data, not whole decades (most points sit within a factor of 2).
if (exists("ymin") && exists("ymax")) {
    set yrange [ymin:ymax]; set format y "%.3g"
    set ytics ymin, (ymax / ymin) ** 0.125, ymax; set mytics 1
}
pt(i) = word("5 7 9 11 13 4 6 8 10 12 14 1 2 3", (i - 1) % 14 + 1) + 0
ps(s) = 0.6 + 0.35 * log(s / 256.0) / log(2.0)

do for [kind in "time bytes"] {
    if (kind eq "time") {
        set xlabel "frame cost / copy-pass cost (minimum over repeats)"
        xcol = 1; front = dir . "/front.dat"; file = out
        set title title . ": error against time"
    } else {
        set xlabel "shadow-map bytes"
        xcol = 3; front = dir . "/front_bytes.dat"; file = out . "_bytes"
        set title title . ": error against memory"
    }
    do for [term in "svg pngcairo"] {
        if (term eq "svg") { set terminal svg size 1000,600 dynamic font "sans,12"; set output file . ".svg" }
        else { set terminal pngcairo size 1000,600 font "sans,10"; set output file . ".png" }
        plot for [i=1:n] sprintf("%s/tech_%d.dat", dir, i) using xcol:2:4:5 \
                 with points pt pt(i) ps variable lc rgb variable notitle, \
             for [i=1:n] sprintf("%s/%s_%d.dat", dir, (kind eq "time" ? "techfront" : "techfront_bytes"), i) \
                 using xcol:2 with lines lw 0.8 dt 2 lc rgb "#999999" notitle, \
             front using xcol:2 with steps lw 2.5 lc rgb "black" title "Pareto front", \
             for [i=1:n] NaN with points pt pt(i) ps 1.1 lc rgb "#444444" title word(names, i), \
             for [i=1:words(sizes)] NaN with points pt 7 ps ps(word(sizes, i) + 0) lc rgb "#888888" \
                 title sprintf("map %s²", word(sizes, i)), \
             for [i=1:words(kernels)] NaN with points pt 7 ps 1.1 lc rgb word(kcolours, i) \
                 title word(kernels, i)
        unset output
    }
}
