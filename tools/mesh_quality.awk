# Quality check of a gmsh MSH 2.2 triangle mesh, run by edp/lib/mesh.idp LoadMesh before
# FreeFEM's gmshload (which stops on any triangle of area below 1e-8, in the mesh's units, with
# only "bug : mes < 1e-8 !").
# Usage: awk -v minq=0.001 -v file=NAME -f tools/mesh_quality.awk NAME.msh
# Quality of a triangle: q = 4 sqrt(3) area / (sum of its squared edge lengths), 1 for an
# equilateral triangle, 0 for a degenerate one. Fails (exit 1, one line on stderr naming the worst
# triangle: number in the file, q, area, centroid) when a triangle's area is below 1e-8 or its q
# is below minq (minq = 0: no quality test).
/^\$Nodes/ { section = "nodes"; next }
/^\$Elements/ { section = "elements"; next }
/^\$End/ { section = ""; next }
section == "nodes" && NF >= 4 { X[$1] = $2; Y[$1] = $3; next }
section == "elements" && NF >= 6 && $2 == 2 {
  ntags = $3; a = $(4 + ntags); b = $(5 + ntags); c = $(6 + ntags)
  area = ((X[b] - X[a]) * (Y[c] - Y[a]) - (X[c] - X[a]) * (Y[b] - Y[a])) / 2
  if (area < 0) area = -area
  l2 = (X[b] - X[a])^2 + (Y[b] - Y[a])^2 + (X[c] - X[b])^2 + (Y[c] - Y[b])^2 + (X[a] - X[c])^2 + (Y[a] - Y[c])^2
  q = l2 > 0 ? 4 * sqrt(3) * area / l2 : 0
  n++; total += area
  if (n == 1 || q < worstQ) { worstQ = q; worstQId = $1; worstQArea = area; worstQx = (X[a] + X[b] + X[c]) / 3; worstQy = (Y[a] + Y[b] + Y[c]) / 3 }
  if (n == 1 || area < minArea) { minArea = area; minAreaId = $1; minAreaQ = q; minAx = (X[a] + X[b] + X[c]) / 3; minAy = (Y[a] + Y[b] + Y[c]) / 3 }
}
END {
  if (n == 0) { print "error: mesh " file " has no triangle" > "/dev/stderr"; exit 1 }
  if (minArea < 1e-8) {
    printf "error: mesh %s: triangle %d (centroid %.6g, %.6g) has area %.3g < 1e-8 (mean %.3g, quality %.3g): FreeFEM's gmshload rejects any triangle below 1e-8 (in the mesh's units)\n", file, minAreaId, minAx, minAy, minArea, total / n, minAreaQ > "/dev/stderr"
    exit 1
  }
  if (minq > 0 && worstQ < minq) {
    printf "error: mesh %s: triangle %d (centroid %.6g, %.6g) has quality %.3g < %g (4 sqrt(3) area / sum of squared edges; area %.3g, mean %.3g): a nearly degenerate triangle (pass -meshminquality 0 to accept it)\n", file, worstQId, worstQx, worstQy, worstQ, minq, worstQArea, total / n > "/dev/stderr"
    exit 1
  }
}
