set terminal pngcairo size 900,520 noenhanced
set output "toyoura_acst_elastic_anisotropy_cv.png"
set datafile separator ','
set title "Cross-validation of toyoura_acst_elastic_anisotropy: error of each fold's experiments"
set ylabel 'RMS of (simulated - measured) / measured range'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set grid ytics
set key below
set xtics rotate by -30
set yrange [0:*]
plot "toyoura_acst_elastic_anisotropy_cv.csv" using 2:xtic(1) skip 1 title 'as fitted (all data)' lc rgb '#1f77b4', \
     '' using 3 skip 1 title 'predicted (fold left out)' lc rgb '#d62728'
