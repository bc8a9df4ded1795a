// A closed straight pipe (capped cylinder) meshed from inside: internal flow, --side
// inward; the caps meet the wall at concave 90-degree edges seen from the fluid.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 3, 0.5};
Mesh.MeshSizeMax = 0.12;
Mesh.Binary = 1;
Mesh.StlOneSolidPerSurface = 0;
