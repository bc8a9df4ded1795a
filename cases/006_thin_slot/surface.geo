// A block with a slot 0.1 wide and 0.7 deep cut into its top: the slot's walls face
// each other closer than twice the requested layer thickness.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Box(2) = {0.95, -0.1, 0.3, 0.1, 1.2, 1};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.1;
Mesh.MeshSizeMin = 0.03;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
