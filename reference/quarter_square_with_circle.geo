// The lower-left quarter [0, lx/2] x [0, ly/2] of square_with_circle.geo's mesh, for a circle centred
// on the plate (cx = lx/2, cy = ly/2): the same O-grid cut along the plate's two mirror lines, which
// are grid lines of the whole mesh, so level n has the same 4 n cells per quarter circle and the same
// cells next to it. A scene that is mirror-symmetric about x = lx/2 and y = ly/2 has a solution that
// is too, and contact_hct.edp and penalty_hct.edp -symmetry quarter solve for it on this quarter alone.
//   gmsh -2 -format msh22 -setnumber n 4 [-setnumber lx 2 -setnumber ly 1 -setnumber r 0.25] quarter_square_with_circle.geo -o mesh.msh
//   [-setnumber grade 30 -setnumber ring 2]: the ring inside the circle graded as in square_with_circle.geo
// Physical tags, read by FreeFEM's gmshload as labels: 1 = clamped boundary, 2 = the circle's arc,
// 3 = the mirror lines; and as regions: 1 = inside the circle, 2 = outside.
If (!Exists(n))
  n = 2;
EndIf
If (!Exists(r))
  r = 0.25;
EndIf
If (!Exists(lx))
  lx = 1;
EndIf
If (!Exists(ly))
  ly = 1;
EndIf
// The centre is the plate's: a -setnumber cx or cy elsewhere is a scene with no mirror lines.
If (Exists(cx))
  If (Abs(cx - lx / 2) > 1e-12 * lx)
    Error("quarter_square_with_circle.geo: the circle's centre cx = %g is not at lx / 2 = %g", cx, lx / 2);
    Abort;
  EndIf
EndIf
If (Exists(cy))
  If (Abs(cy - ly / 2) > 1e-12 * ly)
    Error("quarter_square_with_circle.geo: the circle's centre cy = %g is not at ly / 2 = %g", cy, ly / 2);
    Abort;
  EndIf
EndIf
cx = lx / 2;
cy = ly / 2;
// grade and ring as in square_with_circle.geo: the ring's `ring` n radial cells on one map of k / M1
// whose slope at the central square is `grade` times its slope at the circle.
If (!Exists(grade))
  grade = 1;
EndIf
If (!Exists(ring))
  ring = 1;
EndIf
If (!(grade >= 1 && grade <= 1e6 && ring >= 1 && ring == Round(ring)))
  Error("quarter_square_with_circle.geo: grade must be in [1, 1e6] and ring a whole number >= 1 (grade = %g, ring = %g)", grade, ring);
  Abort;
EndIf
H = 2 * n;      // half of the whole mesh's 4 n: cells along this eighth of the circle, along half a
                // side of the central square and along half a side of the plate
M1 = ring * n;  // cells from the central square out to the circle, as in the whole mesh
M2 = 3 * n;     // cells from the circle out to the plate's corners, as in the whole mesh
a = 0.4 * r;    // half side of the whole mesh's central square
s = Sqrt(0.5);

Point(1) = {cx, cy, 0};                                                        // the centre, on both mirror lines
Point(2) = {cx, cy - a, 0}; Point(3) = {cx - a, cy - a, 0}; Point(4) = {cx - a, cy, 0};  // central square's quarter
Point(5) = {cx, cy - r, 0}; Point(6) = {cx - r * s, cy - r * s, 0}; Point(7) = {cx - r, cy, 0};  // on the circle
Point(8) = {cx, 0, 0}; Point(9) = {0, 0, 0}; Point(10) = {0, cy, 0};          // on the plate's sides
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};       // central square's quarter
Line(5) = {2, 5}; Line(6) = {3, 6}; Line(7) = {4, 7};                         // spokes in
Circle(8) = {5, 1, 6}; Circle(9) = {6, 1, 7};                                 // the circle's quarter
Line(10) = {5, 8}; Line(11) = {6, 9}; Line(12) = {7, 10};                     // spokes out
Line(13) = {8, 9}; Line(14) = {9, 10};                                        // the plate's sides
Transfinite Curve{1, 2, 3, 4, 8, 9, 13, 14} = H + 1;
// The spokes run from the square to the circle: a progression below 1 shrinks the cells outwards.
Transfinite Curve{5, 6, 7} = M1 + 1 Using Progression grade^(-1 / M1);
Transfinite Curve{10, 11, 12} = M2 + 1;
Curve Loop(1) = {-4, -3, -2, -1};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 6, -8, -5};    Plane Surface(2) = {2};
Curve Loop(3) = {3, 7, -9, -6};    Plane Surface(3) = {3};
Curve Loop(4) = {8, 11, -13, -10}; Plane Surface(4) = {4};
Curve Loop(5) = {9, 12, -14, -11}; Plane Surface(5) = {5};
Transfinite Surface{1} = {1, 4, 3, 2} Alternate;
Transfinite Surface{2} = {2, 3, 6, 5} Alternate;
Transfinite Surface{3} = {3, 4, 7, 6} Alternate;
Transfinite Surface{4} = {5, 6, 9, 8} Alternate;
Transfinite Surface{5} = {6, 7, 10, 9} Alternate;
Physical Curve(1) = {13, 14};
Physical Curve(2) = {8, 9};
Physical Curve(3) = {1, 4, 5, 7, 10, 12};
Physical Surface(1) = {1, 2, 3};
Physical Surface(2) = {4, 5};
