// L-shaped block: a concave 90-degree edge where the two arms meet, and concave corners
// at its ends.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Box(2) = {0, 0, 1, 1, 1, 1};
BooleanUnion(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 0.15;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
