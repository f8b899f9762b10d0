// A small housing lid for mtcs's STEP walkthrough and tests (gmsh lid.geo -0 -o lid.step):
// 80 x 50 x 20 mm outside, 2.5 mm walls, open at -z, a round boss (10 mm across, a 4 mm hole)
// inside, four edges rounded (r 5 mm).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 80, 50, 20};
Box(2) = {2.5, 2.5, -1, 75, 45, 18.5};
Cylinder(3) = {40, 25, 0, 0, 0, 20, 5};
Cylinder(4) = {40, 25, -1, 0, 0, 18, 2};
outer() = Fillet{1}{1, 3, 5, 7}{5};
shell() = BooleanDifference{ Volume{outer(0)}; Delete; }{ Volume{2}; Delete; };
boss() = BooleanUnion{ Volume{shell(0)}; Delete; }{ Volume{3}; Delete; };
part() = BooleanDifference{ Volume{boss(0)}; Delete; }{ Volume{4}; Delete; };
