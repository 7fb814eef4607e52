// contact4foam tutorial: hertzSphereTets -- the gmsh geometry and mesh
// (gmsh 4.8, OpenCASCADE kernel; Allrun: gmsh -3 -format msh2, gmshToFoam).
//
// Hertz point contact, the quarter model (x >= 0, z >= 0, symmetry planes
// x = 0 and z = 0) of tutorials/hertzSphere: an elastic sphere (R = 1 m,
// centre (0, R, 0)), its lower half octant y <= R, on an elastic block
// [0, W] x [-H, 0] x [0, W] (W = H = 3 m, 30 a), touching at the origin O,
// the sphere's pole. Tetrahedra.
//
// The sphere is cut by the plane y = 1 - cos 45 deg into the cap around the
// pole (its spherical face is the contact patch sphereContact, 0 to 45 deg
// from the pole as hertzSphere's) and the rest (sphereSurface); both are
// the cellZone sphere.
//
// Sizes (gmsh size fields, a Distance from O and a Threshold per body):
// within rFine = 0.12 m of O (1.2 a at the design load, a = 0.1 m) the
// sphere's tetrahedra have edges of hS = 0.01 m, so that a spans about 10
// slave faces (a/edge = 10.3, a/sqrt|Sf| = 15.6), and the block's
// hB = 0.0125 m (1.25 slave faces per master face: the interface meshes do
// not match); beyond, the sizes grow linearly to hFarS = 0.15 m (sphere)
// and hFarB = 0.4 m (block) at rFar = 1.2 m. 22,313 cells.
// refine (a number > 0) divides every size by itself.
//
// The two bodies share no point: they touch at O only geometrically.
// Physical names: the patches (Allrun sets their types with foamDictionary)
// and the cellZones sphere and block.

SetFactory("OpenCASCADE");
// Bounding boxes of the tessellation: OpenCASCADE's own of the spherical
// faces are too loose to tell the cap from the rest
Geometry.OCCBoundsUseStl = 1;

DefineConstant[ refine = {1, Name "refinement factor"} ];

R   = 1;
W   = 3;
yc  = R - R*Cos(Pi/4);      // the cap's plane
hS  = 0.01/refine;
hB  = 0.0125/refine;
hFarS = 0.15/refine;
hFarB = 0.4/refine;
rFine = 0.12;
rFar  = 1.2;
eps = 1e-4;                 // bounding boxes

// ------------------------------------------------------------- sphere --
Sphere(1) = {0, R, 0, R};
Box(2) = {0, 0, 0, R, yc, R};
Box(3) = {0, yc, 0, R, R - yc, R};
BooleanIntersection(4) = { Volume{1}; }{ Volume{2}; Delete; };
BooleanIntersection(5) = { Volume{1}; Delete; }{ Volume{3}; Delete; };
sph[] = BooleanFragments{ Volume{4, 5}; Delete; }{};

// -------------------------------------------------------------- block --
Box(10) = {0, -W, 0, W, W, W};

// ------------------------------------------------------------ patches --
symX[] = Surface In BoundingBox{-eps, -eps, -eps, eps, R + eps, R + eps};
symZ[] = Surface In BoundingBox{-eps, -eps, -eps, R + eps, R + eps, eps};
top[] = Surface In BoundingBox{-eps, R - eps, -eps, R + eps, R + eps, R + eps};
disc[] = Surface In BoundingBox{-eps, yc - eps, -eps, R + eps, yc + eps, R + eps};
capBox[] = Surface In BoundingBox{-eps, -eps, -eps, R + eps, yc + eps, R + eps};
allS[] = Surface In BoundingBox{-eps, -eps, -eps, R + eps, R + eps, R + eps};
contact[] = capBox[];
contact[] -= symX[];
contact[] -= symZ[];
contact[] -= disc[];
surface[] = allS[];
surface[] -= capBox[];
surface[] -= symX[];
surface[] -= symZ[];
surface[] -= top[];

Physical Surface("sphereContact") = contact[];
Physical Surface("sphereSurface") = surface[];
Physical Surface("sphereTop") = top[];
Physical Surface("sphereSymmetryX") = symX[];
Physical Surface("sphereSymmetryZ") = symZ[];
Physical Surface("blockContact") =
    Surface In BoundingBox{-eps, -eps, -eps, W + eps, eps, W + eps};
Physical Surface("blockSymmetryX") =
    Surface In BoundingBox{-eps, -W - eps, -eps, eps, eps, W + eps};
Physical Surface("blockSymmetryZ") =
    Surface In BoundingBox{-eps, -W - eps, -eps, W + eps, eps, eps};
Physical Surface("blockBottom") =
    Surface In BoundingBox{-eps, -W - eps, -eps, W + eps, -W + eps, W + eps};
Physical Surface("blockSides") =
    {Surface In BoundingBox{W - eps, -W - eps, -eps, W + eps, eps, W + eps},
     Surface In BoundingBox{-eps, -W - eps, W - eps, W + eps, eps, W + eps}};
Physical Volume("sphere") = sph[];
Physical Volume("block") = {10};

// --------------------------------------------------------- mesh sizes --
sphS[] = Abs(Boundary{ Volume{sph[]}; });
sphC[] = Abs(Boundary{ Surface{sphS[]}; });
blkS[] = Abs(Boundary{ Volume{10}; });
blkC[] = Abs(Boundary{ Surface{blkS[]}; });

Field[1] = Distance;
Field[1].PointsList = {Point In BoundingBox{-eps, -eps, -eps, eps, eps, eps}};
Field[2] = Threshold;                 // the sphere
Field[2].InField = 1;
Field[2].SizeMin = hS;
Field[2].SizeMax = hFarS;
Field[2].DistMin = rFine;
Field[2].DistMax = rFar;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].VolumesList = {sph[]};
Field[3].SurfacesList = {sphS[]};
Field[3].CurvesList = {sphC[]};
Field[4] = Threshold;                 // the block
Field[4].InField = 1;
Field[4].SizeMin = hB;
Field[4].SizeMax = hFarB;
Field[4].DistMin = rFine;
Field[4].DistMax = rFar;
Field[5] = Restrict;
Field[5].InField = 4;
Field[5].VolumesList = {10};
Field[5].SurfacesList = {blkS[]};
Field[5].CurvesList = {blkC[]};
Field[6] = Min;
Field[6].FieldsList = {3, 5};
Background Field = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;         // surfaces: Frontal-Delaunay
Mesh.Algorithm3D = 1;       // volumes: Delaunay
Mesh.Optimize = 1;
