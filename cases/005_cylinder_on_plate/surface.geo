// A cylinder standing on a plate: the concave circular junction where the classic
// weighted-average normals give inverted prisms.
SetFactory("OpenCASCADE");
Box(1) = {-2, -2, -0.5, 4, 4, 0.5};
Cylinder(2) = {0, 0, 0, 0, 0, 1.2, 0.5};
BooleanUnion(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.25;
Mesh.MeshSizeMin = 0.05;
Mesh.MeshSizeFromCurvature = 12;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
