// A T-junction of two pipes, meshed from inside (internal flow): the saddle-shaped
// intersection curve is a convex ridge seen from the fluid.
SetFactory("OpenCASCADE");
Cylinder(1) = {-2, 0, 0, 4, 0, 0, 0.4};
Cylinder(2) = {0, 0, 0, 0, 0, 1.5, 0.3};
BooleanUnion(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.12;
Mesh.MeshSizeMin = 0.03;
Mesh.MeshSizeFromCurvature = 16;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
