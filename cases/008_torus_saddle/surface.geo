// A torus: every vertex on its inner half is a saddle (negative Gaussian curvature).
SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 1, 0.35};
Mesh.MeshSizeMax = 0.1;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
