// contact4foam tutorial: contactPatchTestTets -- the gmsh geometry and mesh
// (gmsh 4.8, OpenCASCADE kernel; Allrun: gmsh -3 -format msh2, gmshToFoam).
//
// The contact patch test of tutorials/contactPatchTest3D on tetrahedra: two
// boxes 1 x 1 x 0.5 m (x, y, z) stacked in z, a quarter model (symmetry
// planes x = 0 and y = 0, the faces at x = 1 and y = 1 traction-free).
//   upper box  z in [0, 0.5], tetrahedra of edge hU = 0.1 m; its bottom
//              upperBottom is the SLAVE patch
//   lower box  z in [-0.5, 0], tetrahedra of edge hL = 0.14 m; its top
//              lowerTop is the MASTER patch
// Each box is meshed on its own: they share no point, and their triangles
// at z = 0 do not match (two unstructured surface meshes of different
// sizes). Physical names: the patches (Allrun sets their types with
// foamDictionary) and the cellZones upper and lower.
// refine (a number > 0) divides both sizes by itself.

SetFactory("OpenCASCADE");

DefineConstant[ refine = {1, Name "refinement factor"} ];

hU  = 0.1/refine;
hL  = 0.14/refine;
eps = 1e-6;                 // bounding boxes

Box(1) = {0, 0, 0, 1, 1, 0.5};      // upper
Box(2) = {0, 0, -0.5, 1, 1, 0.5};   // lower

MeshSize{ PointsOf{ Volume{1}; } } = hU;
MeshSize{ PointsOf{ Volume{2}; } } = hL;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;         // surfaces: Frontal-Delaunay
Mesh.Algorithm3D = 1;       // volumes: Delaunay
Mesh.Optimize = 1;

// The two faces at z = 0: each box's own
upS[] = Abs(Boundary{ Volume{1}; });
lowS[] = Abs(Boundary{ Volume{2}; });
z0[] = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
slave[] = z0[];
slave[] -= lowS[];
master[] = z0[];
master[] -= upS[];

Physical Surface("upperBottom") = slave[];
Physical Surface("lowerTop") = master[];
Physical Surface("upperTop") =
    Surface In BoundingBox{-eps, -eps, 0.5 - eps, 1 + eps, 1 + eps, 0.5 + eps};
Physical Surface("lowerBottom") =
    Surface In BoundingBox{-eps, -eps, -0.5 - eps, 1 + eps, 1 + eps, -0.5 + eps};
Physical Surface("symmetryX") =
    Surface In BoundingBox{-eps, -eps, -0.5 - eps, eps, 1 + eps, 0.5 + eps};
Physical Surface("symmetryY") =
    Surface In BoundingBox{-eps, -eps, -0.5 - eps, 1 + eps, eps, 0.5 + eps};
Physical Surface("free") =
    {Surface In BoundingBox{1 - eps, -eps, -0.5 - eps, 1 + eps, 1 + eps, 0.5 + eps},
     Surface In BoundingBox{-eps, 1 - eps, -0.5 - eps, 1 + eps, 1 + eps, 0.5 + eps}};
Physical Volume("upper") = {1};
Physical Volume("lower") = {2};
