# Sourced by the benchmark scripts: errs A B prints the mean and worst relative luminance error
# of the sensor values in A against those in B (rgb per line), as "1.00% 2.68%".
errs() {
  paste "$1" "$2" | awk '{ a = .265*$1+.67*$2+.065*$3; b = .265*$4+.67*$5+.065*$6
    e = (a - b) / b; if (e < 0) e = -e; s += e; if (e > m) m = e; n++ }
    END { printf "%.2f%% %.2f%%", 100 * s / n, 100 * m }'
}
