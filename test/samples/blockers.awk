# blockers.awk: the first blockers of samples.tsv (test/samples/run.sh), counted over the scenes
# povml does not render: "COUNT<TAB>BLOCKER" lines, unsorted. Run with awk -F'\t'.
#
# The blocker of a scene is the keyword of povml's first error:
#   not supported yet: 'wood' in a pigment (used through 'T')  -> wood
#   not supported yet: the function 'trace'                    -> function trace
#   not supported yet: layered textures (…)                    -> layered textures
#   expected … in a texture but found 'checker'                -> checker in texture
#   expected a camera keyword or '}' but found 'cylinder'      -> cylinder in camera
# and for any other message the message itself up to its first colon or semicolon, with quoted
# names and numbers replaced and parentheses left out, so that scenes stopped the same way count
# together. A timeout or a crash is its own blocker; so is a scene that POV-Ray cannot render either
# (an error, not a timeout), whatever povml says.

NR > 1 && $2 != "renders" {
  m = $3
  if ($4 == "error") k = "(POV-Ray fails too)"
  else if ($2 == "timeout") k = "(timeout)"
  else if ($2 == "crash") k = "(crash)"
  else if (m ~ /not supported yet: /) {
    sub(/.*not supported yet: /, "", m)
    if (match(m, /^the function '[^']*'/)) k = "function " substr(m, 15, RLENGTH - 15)
    else if (match(m, /^'[^']*'/)) k = substr(m, 2, RLENGTH - 2)
    else { sub(/ \(.*$/, "", m); sub(/[:;,].*$/, "", m); k = m }
  } else if (m ~ /^expected / && match(m, /but found '[A-Za-z_][A-Za-z_0-9]*'(;.*)?$/)) {
    found = substr(m, RSTART + 11)
    sub(/'.*$/, "", found)
    context = ""
    if (match(m, / in (a |an )?[A-Za-z_]+ but found/)) context = substr(m, RSTART + 4, RLENGTH - 14)
    else if (match(m, /^expected (a |an )?[A-Za-z_]+ keyword/)) context = substr(m, 10, RLENGTH - 17)
    sub(/^(a|an) /, "", context)
    k = found (context == "" ? "" : " in " context)
  } else {
    k = m
    gsub(/'[^']*'/, "…", k); gsub(/"[^"]*"/, "…", k); sub(/ \(.*$/, "", k)
    gsub(/[0-9]+(\.[0-9]+)?/, "N", k); sub(/[:;].*$/, "", k)
  }
  n[k]++
}

END { for (k in n) printf "%d\t%s\n", n[k], k }
