# study_flicker.gp: temporal stability per technique and map size, from the data files shadowlab
# study derives from study.csv (--flicker N). Run by `shadowlab study`; by hand:
#   gnuplot -e "dir='OUT/plots'; out='OUT/flicker'; fseries='hard pcf msm4'; title='classic'" tools/study_flicker.gp
# flicker_<i>.dat: map size, flicker (mean frame-to-frame change of G minus the truth's, as the
# light turns), the truth's own change; one technique each, at its cheapest kernel.
if (!exists("dir")) dir = "plots"
if (!exists("fseries")) fseries = ""
if (!exists("title")) title = ""
if (!exists("out")) out = dir . "/../flicker"
set termoption noenhanced
set grid xtics ytics lc rgb "#dddddd"
set key outside right top
set logscale x 2
set xtics ("256" 256, "512" 512, "1024" 1024, "2048" 2048, "4096" 4096, "128" 128, "64" 64)
set xlabel "shadow-map size"
set ylabel "flicker: mean |G(k+1) − G(k)| − the truth's"
lc(i) = word("#1b9e77 #d95f02 #7570b3 #e7298a #66a61e #e6ab02 #a6761d #666666 #1f78b4 #b2df8a #fb9a99 #cab2d6", (i - 1) % 12 + 1)
pt(i) = word("5 7 9 11 13 4 6 8 10 12 14 1 2 3", (i - 1) % 14 + 1) + 0
n = words(fseries)
do for [term in "svg pngcairo"] {
    if (term eq "svg") { set terminal svg size 1000,560 dynamic font "sans,12"; set output out . ".svg" }
    else { set terminal pngcairo size 1000,560 font "sans,10"; set output out . ".png" }
    set title title . ": flicker as the light turns (0: as steady as the truth)"
    plot for [i=1:n] sprintf("%s/flicker_%d.dat", dir, i) using 1:2 with linespoints \
             pt pt(i) lc rgb lc(i) lw 1.5 title word(fseries, i), \
         0 with lines lc rgb "black" dt 2 notitle
    unset output
}
