// Hexagon of circumradius 1 meshed with triangles of size R/5 (Jha et al. 2021; their code: 91 nodes).
// gmsh -2 -format msh22 hexagon.geo -o hexagon.msh (Gmsh 4.8.4); scaled to each grain by create_peridem_grains.
h = 0.2;
For i In {0:5}
  Point(i+1) = {Cos(i*Pi/3), Sin(i*Pi/3), 0, h};
EndFor
For i In {0:5}
  Line(i+1) = {i+1, (i+1)%6+1};
EndFor
Curve Loop(1) = {1:6};
Plane Surface(1) = {1};
Physical Surface(1) = {1};
