// Quarter of the sleeve's ring (as meshes/ring.geo: Ri = 5.0445 cm, thickness 1 cm, labels 1 inner,
// 2 outer, 3 cut y = 0, 4 cut x = 0) with a layer of thickness eps along the inner surface, meshed
// unstructured: its triangles have one side on one circle and the opposite vertex on the other,
// eps away, nearly degenerate (docs/stability.md, case 6).
// Usage: gmsh -2 -format msh22 -setnumber eps 1.3e-5 sliver.geo -o sliver-thin.msh
//   eps = 1.3e-5: worst quality 0.011 (4 sqrt(3) area / sum of squared edges), smallest area
//                 1.3e-8 m2, just above FreeFEM's limit (gmshload stops below 1e-8);
//   eps = 1e-8:   worst quality 9e-6, area 1e-11 m2 (7e-6 of the mean): rejected up front by
//                 edp/lib/mesh.idp LoadMesh, naming the triangle.
If (!Exists(Ri)) Ri = 0.050445; EndIf
If (!Exists(Hr)) Hr = 0.01; EndIf
If (!Exists(lc)) lc = 0.002; EndIf
If (!Exists(eps)) eps = 1.3e-5; EndIf
Ro = Ri + Hr;
Rl = Ri + eps;  // the layer's outer radius

Point(1) = {0, 0, 0, lc};
Point(2) = {Ri, 0, 0, lc};
Point(3) = {Rl, 0, 0, lc};
Point(4) = {Ro, 0, 0, lc};
Point(5) = {0, Ro, 0, lc};
Point(6) = {0, Rl, 0, lc};
Point(7) = {0, Ri, 0, lc};
Line(1) = {2, 3};
Line(2) = {3, 4};
Circle(3) = {4, 1, 5};
Line(4) = {5, 6};
Line(5) = {6, 7};
Circle(6) = {7, 1, 2};
Circle(7) = {3, 1, 6};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};   // the thin layer
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};   // the rest of the ring

Physical Curve("inner", 1) = {6};
Physical Curve("outer", 2) = {3};
Physical Curve("cut_x", 3) = {1, 2};
Physical Curve("cut_y", 4) = {4, 5};
Physical Surface("ring", 1) = {1, 2};
