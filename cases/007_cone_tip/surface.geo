// A cone with a sharp apex (half-angle 26.6 degrees) on a flat base: a convex conical
// point and a convex circular edge.
SetFactory("OpenCASCADE");
Cone(1) = {0, 0, 0, 0, 0, 1, 0.5, 0};
Mesh.MeshSizeMax = 0.08;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
