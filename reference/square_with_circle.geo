// The rectangle [0, lx] x [0, ly] (the unit square by default) with the obstacle's circle (centre
// (cx, cy), radius r) meshed as an O-grid of transfinite patches: a central square, a ring out to
// the circle, and four patches from the circle to the plate's sides. Mesh vertices lie on the circle (the contact line), 4 n cells along each
// quarter of it, and a vertex at the centre; each n doubled refines every patch the same way, so
// the errors shrink at a steady rate.
//   gmsh -2 -format msh22 -setnumber n 4 [-setnumber lx 2 -setnumber ly 1 -setnumber cx 1 ...] square_with_circle.geo -o mesh.msh
//   [-setnumber grade 30 -setnumber ring 2]
// Physical tags, read by FreeFEM's gmshload as labels: 1 = clamped boundary, 2 = circle; and as
// regions: 1 = inside the circle, 2 = outside (penalty_hct.edp -sampling disk integrates over region 1).
If (!Exists(n))
  n = 2;
EndIf
If (!Exists(r))
  r = 0.25;
EndIf
If (!Exists(cx))
  cx = 0.5;
EndIf
If (!Exists(cy))
  cy = 0.5;
EndIf
If (!Exists(lx))
  lx = 1;
EndIf
If (!Exists(ly))
  ly = 1;
EndIf
// grade > 1 grades the ring inside the circle for the penalty's boundary layer (crosscheck_penalty):
// its `ring` n radial cells shrink geometrically towards the circle. The nodes sit at the fractions
// (1 - grade^(-k/M1)) / (1 - 1/grade), k = 0 ... M1, of the way from the central square to the circle:
// one map of k / M1 for every n, whose slope at the square is `grade` times its slope at the circle.
// So each mesh's ring nodes are every other node of the next one, as on the uniform mesh, and the
// errors can settle to a steady order. (The cells' own ratio, first to last, is grade^((M1-1)/M1).)
If (!Exists(grade))
  grade = 1;
EndIf
If (!Exists(ring))
  ring = 1;
EndIf
If (!(grade >= 1 && grade <= 1e6 && ring >= 1 && ring == Round(ring)))
  Error("square_with_circle.geo: grade must be in [1, 1e6] and ring a whole number >= 1 (grade = %g, ring = %g)", grade, ring);
  Abort;
EndIf
N = 4 * n;      // cells along a quarter of the circle, a side of the central square, a side of the plate
M1 = ring * n;  // cells from the central square out to the circle
M2 = 3 * n;     // cells from the circle out to the plate's corners
a = 0.4 * r;    // half side of the central square
s = Sqrt(0.5);

Point(1) = {cx, cy, 0};
Point(2) = {cx + a, cy - a, 0}; Point(3) = {cx + a, cy + a, 0};
Point(4) = {cx - a, cy + a, 0}; Point(5) = {cx - a, cy - a, 0};
Point(6) = {cx + r * s, cy - r * s, 0}; Point(7) = {cx + r * s, cy + r * s, 0};
Point(8) = {cx - r * s, cy + r * s, 0}; Point(9) = {cx - r * s, cy - r * s, 0};
Point(10) = {lx, 0, 0}; Point(11) = {lx, ly, 0}; Point(12) = {0, ly, 0}; Point(13) = {0, 0, 0};
Line(1) = {2, 3}; Line(2) = {3, 4}; Line(3) = {4, 5}; Line(4) = {5, 2};                          // central square
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8}; Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};      // the circle
Line(9) = {10, 11}; Line(10) = {11, 12}; Line(11) = {12, 13}; Line(12) = {13, 10};               // the plate's sides
Line(13) = {2, 6}; Line(14) = {3, 7}; Line(15) = {4, 8}; Line(16) = {5, 9};                      // spokes in
Line(17) = {6, 10}; Line(18) = {7, 11}; Line(19) = {8, 12}; Line(20) = {9, 13};                  // spokes out
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12} = N + 1;
// The spokes run from the square to the circle: a progression below 1 shrinks the cells outwards.
Transfinite Curve{13, 14, 15, 16} = M1 + 1 Using Progression grade^(-1 / M1);
Transfinite Curve{17, 18, 19, 20} = M2 + 1;
Curve Loop(1) = {1, 2, 3, 4};     Plane Surface(1) = {1};
Curve Loop(2) = {13, 5, -14, -1}; Plane Surface(2) = {2};
Curve Loop(3) = {14, 6, -15, -2}; Plane Surface(3) = {3};
Curve Loop(4) = {15, 7, -16, -3}; Plane Surface(4) = {4};
Curve Loop(5) = {16, 8, -13, -4}; Plane Surface(5) = {5};
Curve Loop(6) = {17, 9, -18, -5}; Plane Surface(6) = {6};
Curve Loop(7) = {18, 10, -19, -6}; Plane Surface(7) = {7};
Curve Loop(8) = {19, 11, -20, -7}; Plane Surface(8) = {8};
Curve Loop(9) = {20, 12, -17, -8}; Plane Surface(9) = {9};
Transfinite Surface{1} = {2, 3, 4, 5} Alternate;
Transfinite Surface{2} = {2, 6, 7, 3} Alternate;
Transfinite Surface{3} = {3, 7, 8, 4} Alternate;
Transfinite Surface{4} = {4, 8, 9, 5} Alternate;
Transfinite Surface{5} = {5, 9, 6, 2} Alternate;
Transfinite Surface{6} = {6, 10, 11, 7} Alternate;
Transfinite Surface{7} = {7, 11, 12, 8} Alternate;
Transfinite Surface{8} = {8, 12, 13, 9} Alternate;
Transfinite Surface{9} = {9, 13, 10, 6} Alternate;
Physical Curve(1) = {9, 10, 11, 12};
Physical Curve(2) = {5, 6, 7, 8};
Physical Surface(1) = {1, 2, 3, 4, 5};
Physical Surface(2) = {6, 7, 8, 9};
