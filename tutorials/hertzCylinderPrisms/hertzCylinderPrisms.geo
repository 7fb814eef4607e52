// contact4foam tutorial: hertzCylinderPrisms -- the gmsh geometry and mesh
// (gmsh 4.8, built-in kernel; Allrun: gmsh -3 -format msh2, gmshToFoam).
//
// Plane-strain Hertz line contact, the half model x >= 0 of
// tutorials/hertzCylinder: a cylinder (R = 0.1 m, centre (0, R)), its lower
// quarter disc, on a block [0, W] x [-H, 0] (W = H = 0.2 m), touching at
// the origin O. Triangles, extruded one layer (dz = 0.01 m) into prisms.
//
// The block's top strip [0, c] x [-d, 0] (c = 12.4 mm, about 2a at the
// design load, a ~ 6.2 mm) is a transfinite surface of nx x ny squares of
// h = c/nx = 0.3875 mm, each cut into two right triangles:
//   skew = 1  every diagonal leans the same way (Left): every slave face's
//             cell is a right triangle whose centre lies h/6 to the side of
//             the face centre, h/3 below it (26.6 degrees non-orthogonal)
//   skew = 2  the diagonals alternate (AlternateLeft): the slave cells lean
//             left and right in turn
//   skew = 0  the strip unstructured (Frontal-Delaunay) with the same
//             boundary points: near-equilateral cells on the slave faces
// nx = 32, ny = 4: a = 6.2 mm spans 16 slave faces, the strip is 1.55 mm
// deep. Elsewhere the triangles are unstructured, h near the contact
// growing to 10 mm (block) and 5 mm (cylinder) away from it; the
// cylinder's faces near O are 0.3 mm (1.3 master faces per slave face: the
// interface meshes do not match). 9,308 cells.
// refine (a number > 0) divides every mesh size by itself (nx, ny times
// it).
//
// The two bodies share no point: they touch at O only geometrically.
// Physical names: the patches (Allrun sets their types with foamDictionary)
// and the cellZones cylinder and block.

DefineConstant[
    skew = {1, Choices {0 = "unstructured", 1 = "left", 2 = "alternate"},
            Name "skew of the block's top strip"},
    refine = {1, Name "refinement factor"}
];

R  = 0.1;        // cylinder radius
W  = 0.2;        // block width and height
dz = 0.01;       // thickness (one layer of prisms)
c  = 0.0124;     // strip width
nx = Round(32*refine);      // slave faces across the strip
ny = Round(4*refine);       // rows of squares in the strip
h  = c/nx;
d  = ny*h;       // strip depth

hCyl   = 0.0003/refine;     // cylinder near O
hBlock = h;                 // block near the strip
hFarC  = 0.005/refine;      // cylinder away from the contact
hFarB  = 0.01/refine;       // block away from the contact

// ------------------------------------------------------------- cylinder --
Point(1) = {0, 0, 0};       // O, the cylinder's lowest point
Point(2) = {0, R, 0};       // C, the centre
Point(3) = {R, R, 0};       // Q
Circle(1) = {1, 2, 3};      // the arc O -> Q: cylinderContact
Line(2) = {3, 2};           // cylinderTop (y = R)
Line(3) = {2, 1};           // cylinderSymmetry (x = 0)
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// ---------------------------------------------------------------- block --
Point(11) = {0, 0, 0};      // b0 = O, not the cylinder's point
Point(12) = {c, 0, 0};      // s1
Point(13) = {c, -d, 0};     // s2
Point(14) = {0, -d, 0};     // s3
Point(15) = {W, 0, 0};      // b4
Point(16) = {W, -W, 0};     // b5
Point(17) = {0, -W, 0};     // b6

Line(11) = {11, 12};        // strip top: blockContact
Line(12) = {12, 13};        // strip right
Line(13) = {13, 14};        // strip bottom
Line(14) = {14, 11};        // strip left: blockSymmetry
Line(15) = {12, 15};        // top beyond the strip: blockContact
Line(16) = {15, 16};        // blockRight
Line(17) = {16, 17};        // blockBottom
Line(18) = {17, 14};        // blockSymmetry

Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};   // the strip
Curve Loop(12) = {15, 16, 17, 18, -13, -12};
Plane Surface(12) = {12};   // the rest of the block

Transfinite Curve{11, 13} = nx + 1;
Transfinite Curve{12, 14} = ny + 1;
If (skew == 1)
    Transfinite Surface{11} = {11, 12, 13, 14} Left;
ElseIf (skew == 2)
    Transfinite Surface{11} = {11, 12, 13, 14} AlternateLeft;
EndIf

// ------------------------------------------------------- mesh sizes --
// Distance from O: the sizes above within c of O, growing linearly to the
// far sizes at 0.06 m
Field[1] = Distance;
Field[1].PointsList = {1, 11};
Field[2] = Threshold;                 // the cylinder
Field[2].InField = 1;
Field[2].SizeMin = hCyl;
Field[2].SizeMax = hFarC;
Field[2].DistMin = c;
Field[2].DistMax = 0.06;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].SurfacesList = {1};
Field[3].CurvesList = {1, 2, 3};
Field[4] = Threshold;                 // the block
Field[4].InField = 1;
Field[4].SizeMin = hBlock;
Field[4].SizeMax = hFarB;
Field[4].DistMin = c;
Field[4].DistMax = 0.06;
Field[5] = Restrict;
Field[5].InField = 4;
Field[5].SurfacesList = {11, 12};
Field[5].CurvesList = {11:18};
Field[6] = Min;
Field[6].FieldsList = {3, 5};
Background Field = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;         // Frontal-Delaunay

// ------------------------------------------- one layer of prisms in z --
cyl[] = Extrude {0, 0, dz} { Surface{1}; Layers{1}; Recombine; };
strip[] = Extrude {0, 0, dz} { Surface{11}; Layers{1}; Recombine; };
rest[] = Extrude {0, 0, dz} { Surface{12}; Layers{1}; Recombine; };
// out[0] the top, out[1] the volume, out[2 ...] the sides in the order of
// the surface's curves

Physical Surface("cylinderContact") = {cyl[2]};
Physical Surface("cylinderTop") = {cyl[3]};
Physical Surface("cylinderSymmetry") = {cyl[4]};
Physical Surface("blockContact") = {strip[2], rest[2]};
Physical Surface("blockSymmetry") = {strip[5], rest[5]};
Physical Surface("blockRight") = {rest[3]};
Physical Surface("blockBottom") = {rest[4]};
Physical Surface("frontAndBack") = {1, 11, 12, cyl[0], strip[0], rest[0]};
Physical Volume("cylinder") = {cyl[1]};
Physical Volume("block") = {strip[1], rest[1]};
