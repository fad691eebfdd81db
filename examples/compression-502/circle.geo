// Unit circle meshed with triangles of size R/5 (Jha et al. 2021, Sec. 4.4; their code: 123 nodes).
// gmsh -2 -format msh22 circle.geo -o circle.msh (Gmsh 4.8.4); scaled to each grain by create_peridem_grains.
h = 0.2;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {0, 1, 0, h};
Point(4) = {-1, 0, 0, h};
Point(5) = {0, -1, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface(1) = {1};
