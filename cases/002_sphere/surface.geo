// Unit sphere centred at the origin.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.MeshSizeMax = 0.15;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
