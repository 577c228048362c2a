// Quarter of the SMA ring (paper Fig. 11, docs/model.md#ring-and-pipe): inner radius Ri, thickness
// Hr, triangles of size lc. Boundary labels (physical lines): 1 inner surface (contact with the
// pipe), 2 outer surface, 3 cut on the x axis (y = 0), 4 cut on the y axis (x = 0); the half ring
// (half = 1) has labels 1, 2 and 3 only.
// Usage: gmsh -2 -format msh22 -setnumber lc 0.001 ring.geo -o ring-coarse.msh
//        gmsh -2 -format msh22 -setnumber nr 16 ring.geo -o ring-l3.msh   (structured)
// Ri = 5 cm is the paper's; the thickness is the project's choice (docs/parameters.md).
If (!Exists(Ri)) Ri = 0.05;  EndIf
If (!Exists(Hr)) Hr = 0.01;  EndIf
If (!Exists(lc)) lc = 0.002; EndIf
Ro = Ri + Hr;

// Half ring (-setnumber half 1), for problems with one mirror symmetry only (paper Fig. 21):
// the upper half, both ends on the x axis; label 3 is then the whole cut y = 0.
If (!Exists(half)) half = 0; EndIf

Point(1) = {0, 0, 0, lc};
Point(2) = {Ri, 0, 0, lc};
Point(3) = {Ro, 0, 0, lc};
If (half)
  Point(4) = {-Ro, 0, 0, lc};
  Point(5) = {-Ri, 0, 0, lc};
  Point(6) = {0, Ro, 0, lc};
  Point(7) = {0, Ri, 0, lc};
  Line(1) = {2, 3};
  Circle(2) = {3, 1, 6};
  Circle(5) = {6, 1, 4};
  Line(3) = {4, 5};
  Circle(4) = {5, 1, 7};
  Circle(6) = {7, 1, 2};
  Curve Loop(1) = {1, 2, 5, 3, 4, 6};
Else
  Point(4) = {0, Ro, 0, lc};
  Point(5) = {0, Ri, 0, lc};
  Line(1) = {2, 3};
  Circle(2) = {3, 1, 4};
  Line(3) = {4, 5};
  Circle(4) = {5, 1, 2};
  Curve Loop(1) = {1, 2, 3, 4};
EndIf
Plane Surface(1) = {1};

// Structured variant (-setnumber nr N): nr layers through the thickness, 5 nr segments along
// each arc, all diagonals the same way, so that every inner-surface node sees the same mesh
// around it and the nodal contact pressures of a uniform fit are uniform (no mesh noise).
If (Exists(nr))
  If (!Exists(nt)) nt = 5 * nr; EndIf
  Transfinite Curve{1, 3} = nr + 1;
  If (half)
    Transfinite Curve{2, 5, 4, 6} = nt + 1;
    Transfinite Surface{1} = {2, 3, 4, 5} Alternate;
  Else
    Transfinite Curve{2, 4} = nt + 1;
    Transfinite Surface{1} Alternate;
  EndIf
EndIf

If (half)
  Physical Curve("inner", 1) = {4, 6};
  Physical Curve("outer", 2) = {2, 5};
  Physical Curve("cut_y0", 3) = {1, 3};
Else
  Physical Curve("inner", 1) = {4};
  Physical Curve("outer", 2) = {2};
  Physical Curve("cut_x", 3) = {1};
  Physical Curve("cut_y", 4) = {3};
EndIf
Physical Surface("ring", 1) = {1};
