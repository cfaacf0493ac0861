// Unit square with the obstacle's circle (centre (0.5, 0.5), radius 0.25) embedded as a curve, so
// mesh vertices and edges lie on the contact circle (10) and no triangle straddles it.
// Mesh size: gmsh -2 -format msh22 -setnumber lc 0.05 square_with_circle.geo -o mesh.msh
// Physical tags, read by FreeFEM's gmshload as labels: 1 = clamped boundary, 2 = circle, 1 = surface.
If (!Exists(lc))
  lc = 0.05;
EndIf
If (!Exists(r))
  r = 0.25;
EndIf

Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The circle as four quarter arcs, their ends on the axes of symmetry of the square.
Point(5) = {0.5, 0.5, 0, lc};
Point(6) = {0.5 + r, 0.5, 0, lc};
Point(7) = {0.5, 0.5 + r, 0, lc};
Point(8) = {0.5 - r, 0.5, 0, lc};
Point(9) = {0.5, 0.5 - r, 0, lc};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};
Curve{5, 6, 7, 8} In Surface{1};
Point{5} In Surface{1};  // a vertex at the centre, where max w is taken

Physical Curve(1) = {1, 2, 3, 4};
Physical Curve(2) = {5, 6, 7, 8};
Physical Surface(1) = {1};
