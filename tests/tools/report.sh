#!/usr/bin/env bash
# The accuracy/time report: runs every chapter's sweeps (the study modes of the chapter executables and the
# benchmark programs), keeps their CSV, draws the plots with gnuplot and writes one page, report/index.md, and
# the same page as HTML beside it (report_html.py: pictures inline, numbers rounded). Beside each chapter's
# tables: the figures its lesson marks (<!--report:KEY ±TOL--> before the number) against this run's, images
# rendered against references side by side with their error (common/tools/rt_compare), and whether each
# reference is good enough for the error measured against it (tests/tools/report_checks.py). The programs'
# console output is kept beside the page as .txt files, never pasted into it.
#
#   tests/tools/report.sh BUILD_DIR OUT_DIR [--quick] [--update-lessons]
#
# --quick          smaller images, fewer sizes and repeats: for class (a few minutes on two cores)
# --update-lessons copy the plots into chapters/NN_name/images/report_*.png, where the lessons show them
#
# Chapters whose executable is not built are left out of the page, with a line saying so. A float-versus-double
# section needs a second build with -DRT_DOUBLE=ON: the script configures and builds it in BUILD_DIR-double
# (chapter 02 only) unless it exists already.
set -euo pipefail

usage() { echo "usage: tests/tools/report.sh BUILD_DIR OUT_DIR [--quick] [--update-lessons]" >&2; exit 2; }
[ $# -ge 2 ] || usage
build=$(cd "$1" && pwd) || usage
out=$2
shift 2
quick=0
update_lessons=0
for flag in "$@"; do
    case "$flag" in
        --quick) quick=1 ;;
        --update-lessons) update_lessons=1 ;;
        *) usage ;;
    esac
done
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
if ! command -v python3 > /dev/null; then
    echo "report: python3 not found: it writes the report's tables (install it: SUDO=\$(command -v sudo); \$SUDO apt-get install python3)" >&2
    exit 2
fi
# Without gnuplot the report still runs every sweep and writes every table; it says which plots are missing.
have_gnuplot=1
if ! command -v gnuplot > /dev/null; then
    have_gnuplot=0
    echo "report: gnuplot not found: the plots are skipped (install it: SUDO=\$(command -v sudo); \$SUDO apt-get install gnuplot-nox)" >&2
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
page="$out/index.md"
start=$(date +%s)

exe() { echo "$build/chapters/$1/$2"; }
have() { [ -x "$(exe "$1" "$2")" ]; }
log() { echo "report: $*" >&2; }

# checks COMMAND ARGS: tests/tools/report_checks.py, which writes the page's tables.
checks() { python3 "$source_dir/tests/tools/report_checks.py" "$@"; }
# csv_to_markdown FILE: the CSV as a Markdown table, its columns named by its header, numbers rounded.
csv_to_markdown() { checks csv "$1"; }
# console_to_markdown FILE [REFERENCE_SPP]: a program's console output (kept beside the page) as tables and
# sentences; with the spp of the reference its errors are measured against, whether it is good enough for them.
console_to_markdown() { checks console "$@"; }

# plot NAME GNUPLOT_COMMANDS: draws $out/NAME.png (800×500) from the commands, which read CSVs in $out.
plot() {
    local name=$1 commands=$2
    if [ "$have_gnuplot" = 0 ]; then
        log "plot $name skipped: gnuplot is not installed"
        return 0
    fi
    (cd "$out" && gnuplot -e "set terminal pngcairo size 800,500 font 'sans,11'; set output '$name.png';
        set datafile separator ','; set key autotitle columnhead; set grid; $commands") \
        || { log "gnuplot failed on $name"; return 1; }
}

# lesson_says NN: the figures lesson NN marks against this run's measurements (nothing when it marks none).
lesson_says() {
    local table
    table=$(checks lesson-table "$source_dir" "$out" "$1")
    [ -n "$table" ] || return 0
    cat >> "$page" <<EOF
### The lesson says / measured

The figures lesson $1 marks (\`<!--report:KEY ±TOL-->\` before the number), against this run's$( [ "$quick" = 1 ] &&
echo " (quick mode renders smaller images with fewer samples than the lesson: the tolerances cover the noise of both)").

$table

EOF
}

# compare_images NAME A.pfm B.pfm CAPTION: A | B | false-colour error | colour bar in $out/NAME.png
# (rt_compare), and the picture with its caption, RMSE and colour scale on the page.
compare_images() {
    local name=$1 a=$2 b=$3 caption=$4 notes rmse scale
    if [ ! -x "$build/common/rt_compare" ]; then
        log "rt_compare is not built: no image comparison $name"
        printf '%s\n\n' "_No image comparison here: \`rt_compare\` is not built._" >> "$page"
        return 0
    fi
    notes=$("$build/common/rt_compare" "$a" "$b" --max-differing 1 --out "$out/$name.png") ||
        { log "rt_compare failed on $name"; return 1; }
    echo "$notes" > "$out/$name.txt"
    rmse=$(echo "$notes" | sed -n 's/.*radiance: RMSE \([^,]*\),.*/\1/p')
    scale=$(echo "$notes" | sed -n 's/.* to \([0-9.e+-]*\) (top, white).*/\1/p')
    cat >> "$page" <<EOF
<img src="$name.png" width="720" style="image-rendering:pixelated">

$caption: A | B | their difference per pixel (the largest channel's, in radiance) in false colour, from black
(0) to white ($(printf '%.3g' "$scale")), with its colour bar. RMSE $(printf '%.3g' "$rmse").

EOF
}

lesson_copy() {  # lesson_copy PLOT CHAPTER_DIR: the plot beside the lesson, when --update-lessons
    [ "$update_lessons" = 1 ] && [ -f "$out/$1.png" ] || return 0
    mkdir -p "$source_dir/chapters/$2/images"
    cp "$out/$1.png" "$source_dir/chapters/$2/images/report_$1.png"
}

if [ "$quick" = 1 ]; then size=(--width 320 --height 180); repeats=1; else size=(); repeats=3; fi

cat > "$page" <<EOF
# What accuracy costs in time

Made by \`tests/tools/report.sh\`$( [ "$quick" = 1 ] && echo " --quick") on $(date -u +%Y-%m-%d), $(nproc) cores. Each table
is the CSV beside this page; each plot is drawn from it by gnuplot. Times are wall-clock on a shared machine: read
the ratios within one table, not the absolute numbers.

EOF
if [ "$have_gnuplot" = 0 ]; then
    cat >> "$page" <<EOF
**No plots in this report:** gnuplot is not installed (\`SUDO=\$(command -v sudo); \$SUDO apt-get install
gnuplot-nox\`). Every table below is complete; the plots beside them are missing.

EOF
fi

# ---------------------------------------------------------------------------------------------------------
if have 01_ray_generation ch01_ray_generation; then
    log "chapter 01: anti-aliasing study"
    (cd "$out" && "$(exe 01_ray_generation ch01_ray_generation)" --aa-study --threads 1 --quiet "${size[@]}" \
        --csv ch01_antialiasing.csv > ch01_antialiasing.txt)
    (cd "$out" && "$(exe 01_ray_generation ch01_ray_generation)" --quiet --width 320 --height 180 --out ch01.png > /dev/null)
    plot ch01_antialiasing "set logscale xy; set xlabel 'samples per pixel'; set ylabel 'RMSE of edge coverage';
        set title 'Anti-aliasing: error against samples (exact coverage of a straight edge)';
        plot 'ch01_antialiasing.csv' using (strcol(1) eq 'uniform' ? \$2 : NaN):3 with linespoints title 'uniform jitter',
             '' using (strcol(1) eq 'stratified' ? \$2 : NaN):3 with linespoints title 'stratified',
             '' using (strcol(1) eq 'center' ? \$2 : NaN):3 with points pointsize 2 title 'pixel centre',
             [1:256] 0.38/sqrt(x) with lines dashtype 2 title 'slope -1/2'"
    lesson_copy ch01_antialiasing 01_ray_generation
    cat >> "$page" <<EOF
## Chapter 01 — ray generation

<img src="ch01.png" width="320"> <img src="ch01_antialiasing.png" width="480">

$(csv_to_markdown "$out/ch01_antialiasing.csv")

The RMSE of each pixel's coverage of a straight edge against its exact area, for each pixel sampler and
number of samples, with the render time: uniform jitter follows the dashed 1/√N line, stratified samples fall
faster, and one centre sample never improves.

EOF
    lesson_says 01
else
    echo "Chapter 01 is not built: left out." >> "$page"
fi

# ---------------------------------------------------------------------------------------------------------
if have 02_intersection ch02_benchmark; then
    log "chapter 02: BVH benchmark and triangle tests"
    max_exponent=$([ "$quick" = 1 ] && echo 5 || echo 6)
    (cd "$out" && "$(exe 02_intersection ch02_benchmark)" --repeats "$repeats" --max-exponent "$max_exponent" \
        --csv ch02_bvh.csv > ch02_bvh.txt) || log "chapter 02: a benchmark target is not met (see ch02_bvh.txt)"
    plot ch02_bvh "set logscale xy; set xlabel 'triangles'; set ylabel 'million rays per second (1 thread)';
        set title 'BVH against brute force (uv spheres)'; set key bottom left;
        plot 'ch02_bvh.csv' using 1:4 with linespoints title 'BVH, camera rays',
             '' using 1:6 with linespoints title 'BVH, random rays',
             '' using 1:8 with linespoints title 'BVH, random rays, any-hit',
             '' using 1:9 with linespoints title 'brute force, random rays'"
    lesson_copy ch02_bvh 02_intersection
    echo "method,triangle_test,ns_per_camera_ray,leak_probe_escaped,leak_probe_rays" > "$out/ch02_triangle_tests.csv"
    for accel in bvh binary none; do
        for test in watertight moller; do
            [ "$accel" = none ] && [ "$quick" = 1 ] && continue
            notes=$(cd "$out" && "$(exe 02_intersection ch02_intersection)" --quiet --accel "$accel" \
                --triangle-test "$test" --out ch02_tmp.png "${size[@]}")
            ns=$(echo "$notes" | sed -n 's/.*: \([0-9.]*\) ns per camera ray.*/\1/p')
            leak=$(echo "$notes" | sed -n 's/.*leak probe, \([0-9]*\) of \([0-9]*\) rays.*/\1,\2/p')
            echo "$accel,$test,$ns,$leak" >> "$out/ch02_triangle_tests.csv"
        done
    done
    rm -f "$out"/ch02_tmp.png "$out"/ch02_tmp.pfm
    (cd "$out" && "$(exe 02_intersection ch02_intersection)" --quiet --width 320 --height 180 --show cost --out ch02_cost.png > /dev/null)
    cat >> "$page" <<EOF
## Chapter 02 — intersection

<img src="ch02_cost.png" width="320"> <img src="ch02_bvh.png" width="480">

$(csv_to_markdown "$out/ch02_bvh.csv")

Rays per second of the BVH and of brute force on meshes of 10³ … 10^$max_exponent triangles ($( [ "$repeats" = 1 ] &&
echo "one run" || echo "median of $repeats runs")): the BVH's rate falls slowly (its boxes per ray grow like log n), brute force's like 1/n.

$(csv_to_markdown "$out/ch02_triangle_tests.csv")

The default scene rendered with each acceleration and triangle test: time per camera ray, and how many rays of
the leak probe (aimed from inside the closed mesh at its vertices and edges) escape through it.

EOF
    # Float against double: the same benchmark and leak probe with Real = double.
    double_build="$build-double"
    # Built every time (make rebuilds only what changed): a double build older than the sources would compare
    # today's float code with yesterday's double code.
    log "building the double-precision build of chapter 02 in $double_build"
    [ -f "$double_build/CMakeCache.txt" ] ||
        cmake -S "$source_dir" -B "$double_build" -DRT_DOUBLE=ON -DCMAKE_BUILD_TYPE=Release > /dev/null
    cmake --build "$double_build" -j "$(nproc)" --target ch02_benchmark ch02_intersection > /dev/null
    log "chapter 02: float against double"
    echo "precision,random_mrays_1_at_1e5,bvh_bytes_per_triangle,moller_leaks,watertight_leaks,leak_probe_rays" \
        > "$out/precision.csv"
    for precision in float double; do
        dir=$([ "$precision" = float ] && echo "$build" || echo "$double_build")
        (cd "$out" && "$dir/chapters/02_intersection/ch02_benchmark" --repeats "$repeats" --max-exponent 5 \
            --csv "precision_$precision.csv" > /dev/null) || true  # its targets are the float build's
        rate=$(awk -F, 'NR > 1 && $1 > 50000 { print $6 }' "$out/precision_$precision.csv")
        bytes=$(awk -F, 'NR > 1 && $1 > 50000 { print $3 }' "$out/precision_$precision.csv")
        moller=$(cd "$out" && "$dir/chapters/02_intersection/ch02_intersection" --quiet --triangle-test moller \
            --out ch02_tmp.png --width 64 --height 36 | sed -n 's/.*leak probe, \([0-9]*\) of.*/\1/p')
        watertight=$(cd "$out" && "$dir/chapters/02_intersection/ch02_intersection" --quiet --out ch02_tmp.png \
            --width 64 --height 36 | sed -n 's/.*leak probe, \([0-9]*\) of \([0-9]*\).*/\1,\2/p')
        echo "$precision,$rate,$bytes,$moller,$watertight" >> "$out/precision.csv"
    done
    rm -f "$out"/ch02_tmp.png "$out"/ch02_tmp.pfm "$out"/precision_*.csv
    cat >> "$page" <<EOF
## Float against double (chapter 02's intersection routines)

$(csv_to_markdown "$out/precision.csv")

The same BVH and rays with \`Real\` = float and = double: rays per second on 10⁵ triangles, the BVH's bytes per
triangle (a node holds two corners: 32 bytes in float, 56 in double), and the leak probe of the default scene's
closed mesh: double precision does not stop Möller–Trumbore from leaking through shared edges; the watertight
test stops it in float.

EOF
    lesson_says 02
else
    echo "Chapter 02 is not built: left out." >> "$page"
fi

# ---------------------------------------------------------------------------------------------------------
if have 03_shadow_rays ch03_shadow_rays; then
    log "chapter 03: ray offset study"
    (cd "$out" && "$(exe 03_shadow_rays ch03_shadow_rays)" --offset-study --quiet "${size[@]}" \
        --csv ch03_offsets.csv > ch03_offsets.txt)
    (cd "$out" && "$(exe 03_shadow_rays ch03_shadow_rays)" --quiet --width 320 --height 180 --out ch03.png > /dev/null)
    # The CSV interleaves the offsets scale by scale; a line joins consecutive rows: the plot reads them grouped.
    (head -n 1 "$out/ch03_offsets.csv"; tail -n +2 "$out/ch03_offsets.csv" | sort -t, -k2,2 -s) > "$out/ch03_offsets_by_offset.csv"
    plot ch03_offsets "set logscale x; set xlabel 'scene scale'; set ylabel 'acne pixels + leak pixels';
        set title 'Ray offsets: wrong pixels against the scene scale'; set key top left;
        plot 'ch03_offsets_by_offset.csv' using (strcol(2) eq 'none' ? \$1 : NaN):(\$6 + \$7) with linespoints title 'no offset',
             '' using (strcol(2) eq 'epsilon' ? \$1 : NaN):(\$6 + \$7) with linespoints title 'fixed epsilon',
             '' using (strcol(2) eq 'robust' ? \$1 : NaN):(\$6 + \$7) with linespoints title 'robust (error bound)'"
    lesson_copy ch03_offsets 03_shadow_rays
    cat >> "$page" <<EOF
## Chapter 03 — shadow rays

<img src="ch03.png" width="320"> <img src="ch03_offsets.png" width="480">

$(csv_to_markdown "$out/ch03_offsets.csv")

The default scene scaled from 10⁻³ to 10⁵, rendered with each way of starting a shadow ray: pixels with acne
(the ray re-hits its own surface) or leaks (the ray starts beyond an occluder) against the exact visibility, and
the cost of computing the offset.

EOF
    lesson_says 03
else
    echo "Chapter 03 is not built: left out." >> "$page"
fi

# ---------------------------------------------------------------------------------------------------------
if have 04_direct_lighting ch04_direct_lighting; then
    log "chapter 04: shadow samples study"
    # At the lesson's size (the analytic scene's own) in quick mode too: the RMSE depends on what the pixels see.
    (cd "$out" && "$(exe 04_direct_lighting ch04_direct_lighting)" --shadow-study --quiet \
        --csv ch04_shadow_samples.csv > ch04_shadow_samples.txt)
    (cd "$out" && "$(exe 04_direct_lighting ch04_direct_lighting)" --quiet --width 320 --height 320 --out ch04.png > /dev/null)
    plot ch04_shadow_samples "set logscale xy; set xlabel 'seconds'; set ylabel 'RMSE against the exact image';
        set title 'Shadow samples: error against time (a plane under a quad light, no occluder: exact by Lambert)';
        plot 'ch04_shadow_samples.csv' using (strcol(1) eq 'independent' ? \$6 : NaN):3 with linespoints title 'independent light samples',
             '' using (strcol(1) eq 'stratified' ? \$6 : NaN):3 with linespoints title 'stratified light samples'"
    lesson_copy ch04_shadow_samples 04_direct_lighting
    cat >> "$page" <<EOF
## Chapter 04 — direct lighting

<img src="ch04.png" width="320"> <img src="ch04_shadow_samples.png" width="480">

$(csv_to_markdown "$out/ch04_shadow_samples.csv")

Shadow samples per pixel against the RMSE to the exact irradiance image (Lambert's formula for a polygon) and
against time, for independent and for stratified points on the light: 4× more independent samples halve the
error; stratified ones fall 4×: the unoccluded light seen from the plane is a smooth integrand, for which
stratification in two dimensions gains a factor √N.

EOF
    lesson_says 04
else
    echo "Chapter 04 is not built: left out." >> "$page"
fi

# ---------------------------------------------------------------------------------------------------------
if have 05_recursive_gi ch05_recursive_gi; then
    log "chapter 05: termination rules in the furnace"
    spp=$([ "$quick" = 1 ] && echo 16 || echo 256)
    (cd "$out" && "$(exe 05_recursive_gi ch05_recursive_gi)" --depth-study --quiet --spp "$spp" \
        --csv ch05_termination.csv > ch05_termination.txt)
    (cd "$out" && "$(exe 05_recursive_gi ch05_recursive_gi)" --quiet --width 200 --height 200 --out ch05.png > /dev/null)
    plot ch05_termination "set logscale xy; set xlabel 'seconds'; set ylabel 'RMSE against Le / (1 - rho)';
        set title 'Termination rules in the furnace box (indirect rays find the light)'; set key off;
        plot 'ch05_termination.csv' using (strcol(5) eq 'hit' ? \$12 : NaN):11 with points pointtype 7,
             '' using (strcol(5) eq 'hit' ? \$12 : NaN):11:(strcol(1) eq 'depth' ? sprintf('depth %d', \$2) : \
                 strcol(1) eq 'throughput' ? sprintf('throughput %g', \$3) : 'roulette') with labels offset 0,1"
    lesson_copy ch05_termination 05_recursive_gi
    cat >> "$page" <<EOF
## Chapter 05 — recursive global illumination

<img src="ch05.png" width="320"> <img src="ch05_termination.png" width="480">

$(csv_to_markdown "$out/ch05_termination.csv")

Each termination rule in the closed furnace box, whose exact radiance is Le/(1−ρ): a maximum depth N is
biased by exactly −ρ^(N+1)/(1−ρ) Le (the \`expected\` column) and costs more with N; the throughput rule is
biased too; Russian roulette is unbiased within its standard error ($spp samples per pixel; \`hit\`: light
found by indirect rays only, \`sampled\`: by light sampling too).

EOF
    lesson_says 05
else
    echo "Chapter 05 is not built: left out." >> "$page"
fi

# ---------------------------------------------------------------------------------------------------------
# Converged references are rendered once and kept in $cache, beside the report.
cache="$out/references"
mkdir -p "$cache"
if have 06_monte_carlo ch06_monte_carlo; then
    log "chapter 06: convergence of every sampling strategy"
    if [ "$quick" = 1 ]; then side=64; max_spp=64; reference_spp=1024; else side=100; max_spp=1024; reference_spp=8192; fi
    (cd "$out" && "$(exe 06_monte_carlo ch06_monte_carlo)" --converge --sampler stratified --quiet --width $side --height $side \
        --max-spp $max_spp --reference-spp $reference_spp --cache "$cache" --csv ch06_convergence.csv > ch06_convergence.txt)
    (cd "$out" && "$(exe 06_monte_carlo ch06_monte_carlo)" --quiet --width 200 --height 200 --out ch06.png > /dev/null)
    ch06_reference=$cache/ch06_reference_ch06_default_${side}x${side}_${reference_spp}spp.pfm
    (cd "$out" && "$(exe 06_monte_carlo ch06_monte_carlo)" --quiet --width $side --height $side --spp 16 \
        --out ch06_mis_16spp.png > /dev/null)
    for plot_file in ch06_convergence_spp ch06_convergence_time; do
        [ -f "$out/$plot_file.png" ] && lesson_copy "$plot_file" 06_monte_carlo
    done
    cat >> "$page" <<EOF
## Chapter 06 — Monte Carlo with importance sampling

<img src="ch06.png" width="320"> <img src="ch06_convergence_spp.png" width="480"> <img src="ch06_convergence_time.png" width="480">

$(csv_to_markdown "$out/ch06_convergence.csv")

Every sampling strategy's RMSE against a converged reference, for samples per pixel from 1 up, with its time
(the slopes of log RMSE against log spp are in the table below; −1/2 is the 1/√N of Monte Carlo): light
sampling and MIS start far lower than the hemisphere strategies, and the efficiency column says which removes
the most noise per second.

$(checks ch06-efficiency "$out/ch06_convergence.csv" "$ch06_reference")

Each strategy at its largest spp: the slope of log RMSE against log spp over every spp (−1/2 is Monte Carlo's
1/√N), its MSE less the reference's own, and the efficiency 1 / (MSE × processor seconds).

EOF
    compare_images ch06_compare "$out/ch06_mis_16spp.pfm" "$ch06_reference" \
        "Chapter 06's MIS at 16 spp (A) against the $reference_spp-spp reference (B), ${side}×${side}"
    lesson_says 06
else
    echo "Chapter 06 is not built: left out." >> "$page"
fi

if have 07_bsdf_refraction ch07_bsdf_refraction; then
    log "chapter 07: Fresnel against Schlick, the depth glass needs"
    (cd "$out" && "$(exe 07_bsdf_refraction ch07_bsdf_refraction)" --fresnel-study --quiet \
        --csv ch07_fresnel.csv > ch07_fresnel.txt)
    plot ch07_fresnel "set xlabel 'angle of incidence (degrees)'; set ylabel 'reflectance R'; set key top left;
        set title 'Fresnel reflectance of glass (eta 1.5): exact against Schlick';
        plot 'ch07_fresnel.csv' using 1:2 with lines lw 2 title 'exact, entering',
             '' using 1:3 with lines dashtype 2 title 'Schlick, entering',
             '' using 1:4 with lines lw 2 title 'exact, leaving',
             '' using 1:5 with lines dashtype 2 title 'Schlick, leaving'"
    lesson_copy ch07_fresnel 07_bsdf_refraction
    # The lesson's setting: cornell.json, its glass sphere, at 150×150 and 64 spp (quick: 64×64, 16 spp).
    cornell="$source_dir/assets/scenes/cornell.json"
    if [ "$quick" = 1 ]; then side=64; spp=16; reference_spp=512; depths=(1 2 4 8 16);
    else side=150; spp=64; reference_spp=4096; depths=(1 2 3 4 6 8 16); fi
    (cd "$out" && "$(exe 07_bsdf_refraction ch07_bsdf_refraction)" --depth-study --quiet --scene "$cornell" \
        --width $side --height $side --spp $spp --reference-spp $reference_spp --depths "${depths[@]}" \
        --cache "$cache" --csv ch07_depth.csv > ch07_depth.txt)
    (cd "$out" && "$(exe 07_bsdf_refraction ch07_bsdf_refraction)" --quiet --width 200 --height 200 --out ch07.png > /dev/null)
    (cd "$out" && "$(exe 07_bsdf_refraction ch07_bsdf_refraction)" --quiet --scene "$cornell" --width $side \
        --height $side --spp $spp --termination depth --max-depth 2 --out ch07_depth2.png > /dev/null)
    plot ch07_depth "set logscale x 2; set logscale y; set xlabel 'maximum depth'; set ylabel 'error';
        set y2label 'seconds'; set y2tics; set ytics nomirror; set key top center;
        set title 'Glass needs depth: error against a converged reference, and time ($spp spp, ${side}x$side)';
        plot 'ch07_depth.csv' using 1:3 with linespoints title 'RMSE',
             '' using 1:(abs(\$5)) with linespoints title '|mean error| (the bias: light lost)',
             '' using 1:6 axes x1y2 with linespoints dashtype 2 title 'time (s, right axis)'"
    cat >> "$page" <<EOF
## Chapter 07 — BSDF refraction

<img src="ch07.png" width="320"> <img src="ch07_fresnel.png" width="480">

$(console_to_markdown "$out/ch07_fresnel.txt")

Schlick's approximation against the exact Fresnel equations of a dielectric (η = 1.5), entering and leaving
the glass: its largest and mean error, where it is largest, and what one evaluation of each costs (the plot:
the CSV's angles, one degree apart).

<img src="ch07_depth.png" width="480">

$(checks ch07-depth "$out/ch07_depth.csv" $reference_spp)

\`cornell.json\` (its glass sphere) rendered with a fixed maximum depth against a converged reference
(Russian roulette, $reference_spp spp): the bias (light lost) falls with depth, the time grows with it.

EOF
    compare_images ch07_compare "$out/ch07_depth2.pfm" "$cache/ch07_reference_cornell_${side}x${side}_${reference_spp}spp.pfm" \
        "Chapter 07 at maximum depth 2 (A) against the reference (B): the light that needs more bounces is lost, most of all through the glass"
    lesson_says 07
else
    echo "Chapter 07 is not built: left out." >> "$page"
fi

if have 08_forward_tracing ch08_forward_tracing; then
    log "chapter 08: forward against reverse"
    if [ "$quick" = 1 ]; then side=32; reference_spp=1024; forward=(--study-paths 1000000 --glass-reference-spp 512);
    else side=100; reference_spp=8192; forward=(); fi
    (cd "$out" && "$(exe 08_forward_tracing ch08_forward_tracing)" --forward-study --quiet --study-size $side \
        --reference-spp $reference_spp "${forward[@]}" --cache "$cache" --csv ch08_forward.csv > ch08_forward.txt)
    (cd "$out" && "$(exe 08_forward_tracing ch08_forward_tracing)" --quiet --width 200 --height 200 --out ch08.png > /dev/null)
    # Its sections 1 and 3; section 2 (time to the same RMSE) is the CSV's, its times interpolated only.
    awk '/^2\. /{ skip = 1 } /^3\. /{ skip = 0 } !skip' "$out/ch08_forward.txt" > "$out/ch08_forward_1_3.txt"
    plot ch08_forward "set logscale xy; set xlabel 'seconds'; set ylabel 'RMSE against the converged reference';
        set title 'Light paths against camera paths: error against time as the paths per pixel grow (${side}x$side)';
        plot 'ch08_forward.csv' using (strcol(1) eq 'forward (connect)' ? \$4 : NaN):3 with linespoints title 'light tracer, connected (4 to 256 paths per pixel)',
             '' using (strcol(1) eq 'reverse (mis)' ? \$4 : NaN):3 with linespoints title 'path tracer, MIS (4 to 64 spp)',
             '' using (strcol(1) eq 'reverse (brdf)' ? \$4 : NaN):3 with linespoints title 'path tracer, BRDF sampling (4 to 64 spp)'"
    cat >> "$page" <<EOF
## Chapter 08 — forward (light) tracing

<img src="ch08.png" width="320"> <img src="ch08_forward.png" width="480">

$(checks ch08-time "$out/ch08_forward.csv" "$cache/ch06_reference_ch06_default_${side}x${side}_${reference_spp}spp.pfm")

Tracing from the lights on chapter 06's Cornell box: the light tracer and chapter 06's path tracer at a
growing number of paths per pixel, their RMSE against the converged reference and their time, and the time the
light tracer needs to reach each of the path tracer's RMSEs, read off its own curve between the two measured
points around it: an RMSE outside the light tracer's measured ones is not extrapolated.

$(console_to_markdown "$out/ch08_forward_1_3.txt")

The fraction of light paths that reach the camera through a lens and by connecting each bounce to it, and
where forward tracing wins (caustics) and loses (what mirrors and glass show), region by region.

EOF
    lesson_says 08
else
    echo "Chapter 08 is not built: left out." >> "$page"
fi

if have 09_participating_media ch09_participating_media; then
    log "chapter 09: walk lengths, free flight, the walk's knobs, the cost of the volume hooks"
    ch09=$(exe 09_participating_media ch09_participating_media)
    milk="$source_dir/assets/scenes/ch09_milk_matched.json"
    if [ "$quick" = 1 ]; then walk=(--study-paths 1000); knob_reference_spp=256; knob=(--width 32 --height 32 --spp 16);
        bench=(3 100 4);
    else walk=(--study-paths 8000); knob_reference_spp=2048; knob=(--width 48 --height 48 --spp 32); bench=(9 160 8); fi
    (cd "$out" && "$ch09" --walk-study --quiet "${walk[@]}" > ch09_walk.txt)
    (cd "$out" && "$ch09" --free-flight-study --quiet > ch09_free_flight.txt)
    (cd "$out" && "$ch09" --knob-study --quiet --scene "$milk" "${knob[@]}" --reference-spp $knob_reference_spp \
        --caps 1 2 4 8 16 32 64 256 10000 > ch09_knobs.txt)
    (cd "$out" && "$(dirname "$ch09")/ch09_benchmark" "${bench[@]}" > ch09_benchmark.txt)
    (cd "$out" && "$ch09" --quiet --scene "$milk" --out ch09.png > /dev/null)
    cat >> "$page" <<EOF
## Chapter 09 — participating media

<img src="ch09.png" width="320">

$(console_to_markdown "$out/ch09_walk.txt")

Random walks in a sphere of a medium: the scattering events a path makes against the mean free path and the
albedo, and what a path costs.

$(console_to_markdown "$out/ch09_free_flight.txt")

Free flight in a chromatic medium: spectral MIS (the average density over the channels) against the naive
density of the channel that drew the distance.

$(console_to_markdown "$out/ch09_knobs.txt" $knob_reference_spp)

The walk's knobs on the index-matched milk box: a cap on scattering events (a bias) and Russian roulette in
the medium, error against an uncapped reference and time.

$(console_to_markdown "$out/ch09_benchmark.txt")

What the volume hooks cost a scene without media: chapter 09 against chapter 07 on cornell.json.

EOF
    lesson_says 09
else
    echo "Chapter 09 is not built: left out." >> "$page"
fi

if have 10_denoising ch10_denoising; then
    log "chapter 10: the denoisers against a converged reference"
    if [ "$quick" = 1 ]; then study_reference_spp=1024; study=(--width 100 --height 100 --spp 16 --runs 2);
    else study_reference_spp=4096; study=(--width 300 --height 300 --spp 16 --runs 4); fi
    mkdir -p "$out/ch10_crops"
    (cd "$out" && "$(exe 10_denoising ch10_denoising)" --study --sweeps --quiet "${study[@]}" \
        --reference-spp $study_reference_spp --cache "$cache" --crops "$out/ch10_crops" > ch10_study.txt)
    (cd "$out" && "$(exe 10_denoising ch10_denoising)" --study --quiet "${study[@]}" --reference-spp $study_reference_spp \
        --scene "$source_dir/assets/scenes/cornell.json" --cache "$cache" > ch10_cornell.txt)
    cp "$out/ch10_crops/ch10_whole.png" "$out/ch10_whole.png"
    cat >> "$page" <<EOF
## Chapter 10 — denoising

<img src="ch10_whole.png" width="640">

$(console_to_markdown "$out/ch10_study.txt" $study_reference_spp)

The joint bilateral and the edge-avoiding à-trous filters on chapter 10's box (its glass sphere and a comb of
thin rods) against a converged reference: their error, SSIM and time with the render's; the samples plain
path tracing needs for the same relative MSE, and how many times sooner the filter gets there counting its
own time (an equal-error spp past the last plain render is not extrapolated: "not reached in the measured
range"); their bias over independent runs; the regions where they lose to plain path tracing at that
equal-error spp; and each parameter swept alone. The strips are reference, noisy, bilateral, à-trous.

$(console_to_markdown "$out/ch10_cornell.txt" $study_reference_spp)

The same on \`cornell.json\` at its benchmark setting for this chapter (300×300, 16 spp).

EOF
    lesson_says 10
else
    echo "Chapter 10 is not built: left out." >> "$page"
fi

find "$out" -maxdepth 1 -name "*.pfm" -delete
echo "_The report took $(( $(date +%s) - start )) s._" >> "$page"
log "wrote $page in $(( $(date +%s) - start )) s"
# The same page as HTML, to project in class: pictures inline, numbers rounded, console output folded.
if command -v python3 > /dev/null; then
    python3 "$source_dir/tests/tools/report_html.py" "$page"
else
    log "python3 not found: no index.html beside $page (install it: SUDO=\$(command -v sudo); \$SUDO apt-get install python3)"
fi
