#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# report.html opens with its data sheet, and printing the page prints that sheet alone on one page of A4
# and of Letter at 100%, with no text under 8 pt: RS1 (NCHRP Report 350 test 3-11 as run) and APS3 (ASTM
# F2656 as run) are printed to PDF by headless chromium (`--print-to-pdf`, the paper chosen by an @page
# size added to a copy, as a print dialog would), and each PDF must have exactly one page of that paper;
# the page's print styles and the sheet's own may set no font size under 8 pt; the sheet, as chromium
# builds it (--dump-dom), names the test and gives each criterion its verdict. "Print the whole report"
# prints no plot and no word wider than the printable width of A4 or Letter. Skipped (77) in a build
# without the report page (node, npm) or without chromium.
source "$(dirname "$0")/lib.sh"

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "skipped: no chromium (bash scripts/install-deps.sh installs it)"
    exit 77
fi
"$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1" --report >"$tmp/rs1.out" 2>&1
check "RS1 runs with --report" '[ $? -eq 0 ] || { cat "$tmp/rs1.out"; false; }'
if [ ! -s "$tmp/rs1/report.html" ]; then
    echo "skipped: this cablesim was built without the report page (node and npm)"
    exit 77
fi
"$cs" run examples/aps3.yaml -o "$tmp/aps3" --report >"$tmp/aps3.out" 2>&1
check "APS3 runs with --report" '[ $? -eq 0 ] || { cat "$tmp/aps3.out"; false; }'

flags=(--headless --no-sandbox --disable-gpu --no-pdf-header-footer --run-all-compositor-stages-before-draw
    --virtual-time-budget=10000 --user-data-dir="$tmp/profile")

# pages PDF: the number of pages (pdfinfo where poppler-utils is installed, else the page objects)
pages() {
    if command -v pdfinfo >/dev/null; then
        pdfinfo "$1" | awk '/^Pages:/ {print $2}'
    else
        grep -a -c -E '/Type */Page([^s]|$)' "$1"
    fi
}

# The pages in chromium: the browser's work on the pages the runs above wrote, in the plain suite (under
# the sanitizers the two runs with --report are this script's representative case).
if plain_only "the pages in chromium: the data sheets and their prints on A4 and Letter"; then
    for run in rs1 aps3; do
        html="$tmp/$run/report.html"
        "$browser" "${flags[@]}" --dump-dom "file://$html" 2>/dev/null | tr -d '\n' >"$tmp/$run.dom"
        # the first section of the page's main part is the sheet, built
        check "$run: the page opens with the data sheet" \
            'grep -q -E "<main>(<noscript>.*</noscript>)? *<section id=\"datasheet-section\"> *<div id=\"datasheet\"><div class=\"sheet\"><h2>Data sheet: " "$tmp/$run.dom"'
        for paper in A4 letter; do
            # the paper as the print dialog would choose it: an @page size in a copy of the page
            sed "s|</head>|<style>@page { size: $paper; }</style></head>|" "$html" >"$tmp/$run-$paper.html"
            "$browser" "${flags[@]}" --print-to-pdf="$tmp/$run-$paper.pdf" "file://$tmp/$run-$paper.html" >/dev/null 2>&1
            check "$run, $paper: a PDF" '[ "$(head -c 5 "$tmp/$run-$paper.pdf" 2>/dev/null)" = "%PDF-" ]'
            n=$(pages "$tmp/$run-$paper.pdf" 2>/dev/null)
            check "$run, $paper: exactly one page (got ${n:-none})" '[ "$n" = 1 ]'
            # A4 is 595.3 x 841.9 pt, Letter 612 x 792 pt (within a point)
            size=$(grep -a -o -E "/MediaBox *\[0 0 [0-9.]+ [0-9.]+" "$tmp/$run-$paper.pdf" | head -1 | awk '{print $4, $5}')
            want=$([ $paper = A4 ] && echo "595.3 841.9" || echo "612 792")
            check "$run, $paper: the page is $paper ($want pt; got ${size:-none})" \
                'awk -v s="$size" -v w="$want" "BEGIN {split(s, a); split(w, b); exit !(a[1] != \"\" && (a[1] - b[1])^2 < 1 && (a[2] - b[2])^2 < 1)}"'
        done
    done

    # The whole report printed ("Print the whole report": body.print-all, here in a copy) from a window
    # wider than the paper, on A4 and Letter: no plot and no word beyond the printable width (the page's
    # 10-mm margins), each plot drawn for the paper before the print (plots.js) and scaled to the page by
    # the print styles, not cut at the page's edge. A plot printed as a picture has its width in the PDF
    # (pdfimages: pixels over pixels per inch); one drawn as the print began is text and lines (pdftotext).
    if command -v pdfimages >/dev/null && command -v pdftotext >/dev/null; then
        for paper in A4 letter; do
            sed "s|<body>|<body class=\"print-all\">|; s|</head>|<style>@page { size: $paper; }</style></head>|" \
                "$tmp/rs1/report.html" >"$tmp/all-$paper.html"
            "$browser" "${flags[@]}" --window-size=1600,1000 --print-to-pdf="$tmp/all-$paper.pdf" \
                "file://$tmp/all-$paper.html" >/dev/null 2>&1
            n=$(pages "$tmp/all-$paper.pdf" 2>/dev/null)
            check "RS1 whole, $paper: printed on pages (got ${n:-none})" '[ "${n:-0}" -gt 1 ]'
            width=$([ $paper = A4 ] && echo 595.3 || echo 612)
            wide=$(pdfimages -list "$tmp/all-$paper.pdf" | awk -v w="$width" \
                'NR > 2 && $3 == "image" && $4 / $13 * 72 > w - 2 * 28.35 + 1 {printf "%s px at %s ppi on page %s; ", $4, $13, $1}')
            check "RS1 whole, $paper: no picture wider than the printable width${wide:+ (found: $wide)}" '[ -z "$wide" ]'
            out=$(pdftotext -bbox "$tmp/all-$paper.pdf" - | grep -o -E '<word xMin="[0-9.]+" yMin="[0-9.]+" xMax="[0-9.]+"[^>]*>[^<]*' |
                awk -F'"' -v w="$width" '$2 < 28.35 - 1 || $6 > w - 28.35 + 1 {sub(/.*>/, ""); printf "%s; ", $0}')
            check "RS1 whole, $paper: no word beyond the printable width${out:+ (found: $out)}" '[ -z "$out" ]'
            check "RS1 whole, $paper: the plots printed" 'pdftotext "$tmp/all-$paper.pdf" - | grep -q "Where the energy went"'
        done
    else
        echo "skipped: the whole report's print width (no pdfimages or pdftotext: poppler-utils)"
    fi

    # RS1 is NCHRP Report 350's test 3-11 as run: each of its criteria on the sheet with a verdict, D and K
    # not judged (never a pass); APS3's truck: ASTM F2656's penetration designation
    dom="$tmp/rs1.dom"
    check "RS1's sheet names its test" 'grep -q "NCHRP Report 350 test 3-11 as run" "$dom"'
    for id in A D F L K M; do
        check "RS1's sheet: criterion $id with a verdict" \
            'grep -q -E "<tr><th scope=\"row\">$id</th><td>[^<]*</td><td class=\"verdict (pass|fail|nj)\">(pass|FAIL|not judged)</td>" "$dom"'
    done
    for id in D K; do
        check "RS1's sheet: $id not judged" 'grep -q "<th scope=\"row\">$id</th><td>[^<]*</td><td class=\"verdict nj\">not judged</td>" "$dom"'
    done
    check "RS1's sheet: the not-judged line" 'grep -q "Not judged (D, K): the model cannot tell; no pass is implied." "$dom"'
    # the sheet's OIV as the terminal prints it: the occupant impact line's two values, to 2 decimals
    oiv=$(grep -oE "OIV [0-9.]+ m/s \([0-9.]+ ft/s\) longitudinal, [0-9.]+ m/s" "$tmp/rs1.out" | awk '{ print $2 ", " $7 }')
    check "RS1's sheet: the occupant impact velocities as the terminal gives them ($oiv m/s)" \
        '[ -n "$oiv" ] && grep -qF "<th scope=\"row\">OIV long., lat.</th><td>$oiv m/s</td>" "$dom"'
    # with --occupant-at the sheet says its occupant risk is a point's, the criteria the CG's; RS1's has no
    # such row
    "$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1p" --occupant-at "30 cm,0.4 m,0.2 m" --report >/dev/null 2>&1
    "$browser" "${flags[@]}" --dump-dom "file://$tmp/rs1p/report.html" 2>/dev/null | tr -d '\n' >"$tmp/rs1p.dom"
    check "a sheet at a point of the vehicle says so; RS1's at the CG does not" \
        'grep -qF "<th scope=\"row\">at a point</th><td>0.30, 0.40, 0.20 m from the CG; criteria: the CG" "$tmp/rs1p.dom" && ! grep -qF "<th scope=\"row\">at a point</th>" "$dom"'
    check "RS1's story gives the impact angle as the sheet does (25.7 deg)" \
        'grep -q "<th scope=\"row\">angle</th><td>25.7°</td>" "$dom" && grep -q "at 25.7° to the barrier line" "$dom"'
    check "RS1's sheet: five sequential pictures, top and side" '[ "$(grep -o "<svg[^>]*class=\"pic top\"" "$dom" | wc -l)" = 5 ] && [ "$(grep -o "<svg[^>]*class=\"pic side\"" "$dom" | wc -l)" = 5 ]'
    check "APS3's sheet: its ASTM F2656 designation" 'grep -q -E "<th scope=\"row\">ASTM F2656</th><td>[^<]*</td><td class=\"verdict rating\">M40/P[1-4]</td>" "$tmp/aps3.dom"'
fi

# no font size under 8 pt in the print styles (the @media print block) nor in the sheet's own rules
css=$(sed -n '/<style>/,/<\/style>/p' "$tmp/rs1/report.html")
print=$(awk '/@media print \{/ {on = 1} on {print} on && /^\}/ {on = 0}' <<<"$css")
sheet=$(grep -E '^(\.sheet|table\.sheet|\.verdict)' <<<"$css")
check "the page has print styles" '[ -n "$print" ] && grep -q "datasheet-section" <<<"$print"'
small=$( (printf '%s\n%s\n' "$print" "$sheet") | grep -o -E 'font-size: *[0-9.]+(px|pt)' |
    awk '{v = $2 + 0; if ($2 ~ /px/) v *= 0.75; if (v < 8) print}')
check "no print or sheet font size under 8 pt${small:+ (found: $small)}" '[ -z "$small" ]'
check "the sheet's font sizes are in pt" '! grep -o -E "font-size: *[0-9.]+px" <<<"$sheet" | grep -q .'

finish
