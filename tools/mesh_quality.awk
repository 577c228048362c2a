# Quality check of a gmsh MSH 2.2 triangle mesh, run by edp/lib/mesh.idp LoadMesh before
# FreeFEM's gmshload (which stops on any triangle of area below 1e-8, in the mesh's units, with
# only "bug : mes < 1e-8 !").
# Usage: awk -v minq=0.001 -v file=NAME -f tools/mesh_quality.awk NAME.msh
# Quality of a triangle: q = 4 sqrt(3) area / (sum of its squared edge lengths), 1 for an
# equilateral triangle, 0 for a degenerate one. Fails (exit 1, one line on stderr naming the worst
# triangle: number in the file, q, area, centroid) when a triangle's area is below 1e-8 or its q
# is below minq (minq = 0: no quality test).
# Also fails, naming the file, on what would make gmshload abort or mislead: another format than
# MSH 2 (gmsh 4 writes MSH 4 unless -format msh22), a file cut off before $EndElements or holding
# fewer elements than it declares, a triangle on a node the file does not define, and a clockwise
# triangle (FreeFEM's meshes are counter-clockwise; gmshload stops on an assertion).
/^\$MeshFormat/ { section = "format"; next }
section == "format" { version = $1; binary = $2; section = ""; next }
/^\$Nodes/ { section = "nodes"; next }
/^\$Elements/ { section = "elements"; declared = -1; next }
/^\$EndElements/ { section = ""; endElements = 1; next }
/^\$End/ { section = ""; next }
section == "elements" && declared < 0 { declared = $1; next }
section == "elements" { elements++ }
section == "nodes" && NF >= 4 { X[$1] = $2; Y[$1] = $3; next }
section == "elements" && NF >= 6 && $2 == 2 {
  ntags = $3; a = $(4 + ntags); b = $(5 + ntags); c = $(6 + ntags)
  if (!(a in X) || !(b in X) || !(c in X)) { if (!missingNode) missingNode = $1; next }
  area = ((X[b] - X[a]) * (Y[c] - Y[a]) - (X[c] - X[a]) * (Y[b] - Y[a])) / 2
  if (area < 0) { if (!clockwise) { clockwise = $1; cwx = (X[a] + X[b] + X[c]) / 3; cwy = (Y[a] + Y[b] + Y[c]) / 3 }; area = -area }
  l2 = (X[b] - X[a])^2 + (Y[b] - Y[a])^2 + (X[c] - X[b])^2 + (Y[c] - Y[b])^2 + (X[a] - X[c])^2 + (Y[a] - Y[c])^2
  q = l2 > 0 ? 4 * sqrt(3) * area / l2 : 0
  n++; total += area
  if (n == 1 || q < worstQ) { worstQ = q; worstQId = $1; worstQArea = area; worstQx = (X[a] + X[b] + X[c]) / 3; worstQy = (Y[a] + Y[b] + Y[c]) / 3 }
  if (n == 1 || area < minArea) { minArea = area; minAreaId = $1; minAreaQ = q; minAx = (X[a] + X[b] + X[c]) / 3; minAy = (Y[a] + Y[b] + Y[c]) / 3 }
}
END {
  if (version == "") { print "error: mesh " file " is not a gmsh MSH file (no $MeshFormat)" > "/dev/stderr"; exit 1 }
  if (version + 0 >= 3 || version + 0 < 2) {
    print "error: mesh " file " is MSH " version ": FreeFEM's gmshload reads MSH 2.2 only (gmsh -format msh22)" > "/dev/stderr"; exit 1
  }
  if (binary != 0) { print "error: mesh " file " is a binary MSH file: gmshload reads ASCII MSH 2.2 (gmsh -format msh22 without -bin)" > "/dev/stderr"; exit 1 }
  if (declared == "" || declared < 0) { print "error: mesh " file " is cut off before its elements (an interrupted gmsh or copy? run 'make meshes')" > "/dev/stderr"; exit 1 }
  if (!endElements || elements != declared) {
    printf "error: mesh %s is cut off: %d of the %d elements it declares, %s (an interrupted gmsh or copy? run 'make meshes')\n", file, elements, declared, endElements ? "then $EndElements" : "and no $EndElements" > "/dev/stderr"; exit 1
  }
  if (missingNode) { printf "error: mesh %s: triangle %d uses a node the file does not define\n", file, missingNode > "/dev/stderr"; exit 1 }
  if (clockwise) {
    printf "error: mesh %s: triangle %d (centroid %.6g, %.6g) is clockwise: FreeFEM needs counter-clockwise triangles (regenerate the mesh with gmsh)\n", file, clockwise, cwx, cwy > "/dev/stderr"; exit 1
  }
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
