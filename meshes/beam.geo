// Cantilever beam of the paper's section 3.2 (Fig. 9): length L, height H, unstructured triangles
// of size lc (Frontal-Delaunay). Boundary labels (physical lines): 1 bottom, 2 loaded end (x = L),
// 3 top, 4 clamped end (x = 0). The Makefile makes three meshes whose node and triangle counts are
// within 10 % of the paper's 325/580, 808/1504, 2527/4860:
//   gmsh -2 -format msh22 -setnumber lc 0.0021 beam.geo -o beam-coarse.msh   (345 / 582)
//   lc 0.00125 -> beam-medium.msh (852 / 1526),  lc 0.0007 -> beam-fine.msh (2529 / 4740)
// The dimensions (0.1 m x 0.01 m) are the project's choice: the paper gives none
// (docs/parameters.md).
If (!Exists(L))  L = 0.1;  EndIf
If (!Exists(H))  H = 0.01;  EndIf
If (!Exists(lc)) lc = 0.002; EndIf
Point(1) = {0, 0, 0, lc};
Point(2) = {L, 0, 0, lc};
Point(3) = {L, H, 0, lc};
Point(4) = {0, H, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("loaded", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("clamped", 4) = {4};
Physical Surface("beam", 1) = {1};
