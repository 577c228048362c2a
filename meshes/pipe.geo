// Quarter of the elastic pipe (docs/model.md#elastic-pipe; the 2D sleeve scenes with -pipeE > 0):
// outer radius R, inner radius Ri (0: a solid shaft, a quarter disk), triangles of size lc.
// Boundary labels (physical lines), as the ring's (meshes/ring.geo): 1 inner surface (hollow pipe
// only), 2 outer surface (contact with the ring), 3 cut on the x axis (y = 0), 4 cut on the y axis
// (x = 0). The scenes stretch it radially to -pipeRi .. -pipeA, and to an ellipse's semi-axes.
// Usage: gmsh -2 -format msh22 -setnumber R 0.0505 -setnumber lc 0.002 pipe.geo -o pipe-solid.msh
If (!Exists(R)) R = 0.0505; EndIf
If (!Exists(Ri)) Ri = 0; EndIf
If (!Exists(lc)) lc = 0.002; EndIf

Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
If (Ri > 0)
  Point(4) = {Ri, 0, 0, lc};
  Point(5) = {0, Ri, 0, lc};
  Line(1) = {4, 2};
  Circle(2) = {2, 1, 3};
  Line(3) = {3, 5};
  Circle(4) = {5, 1, 4};
  Curve Loop(1) = {1, 2, 3, 4};
  Physical Curve("inner", 1) = {4};
Else
  Line(1) = {1, 2};
  Circle(2) = {2, 1, 3};
  Line(3) = {3, 1};
  Curve Loop(1) = {1, 2, 3};
EndIf
Plane Surface(1) = {1};
Physical Curve("outer", 2) = {2};
Physical Curve("cut_x", 3) = {1};
Physical Curve("cut_y", 4) = {3};
Physical Surface("pipe", 1) = {1};
