// Unit cube: 12 convex 90-degree edges and 8 convex corners.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.MeshSizeMax = 0.125;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
