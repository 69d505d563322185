// profsubd's limit surface in OpenSCAD's CSG: the built-in bottle, tessellated by profsubd
// (watertight: points on shared edges are computed once), bored along its axis from the neck
// down (difference with a cylinder) and standing on a base plate (union with a cube).
//
//   profsubd profile -o bottle.obj && profsubd tessellate bottle.obj --rate 2 -o bottle.stl
//   openscad -o out.stl profsubd_csg.scad                        # STL input
//   openscad -o out.stl -D 'model="bottle.off"' profsubd_csg.scad  # OFF input (profsubd tessellate ... -o bottle.off)
//
// The bottle spans x in [-1.25, 1.25], y in [-0.92, 0.92], z in [0, 4.6].
model = "bottle.stl";

union() {
    difference() {
        import(model, convexity = 4);
        translate([0, 0, 1]) cylinder(h = 4, r = 0.3, $fn = 32);
    }
    translate([-1.5, -1.5, -0.3]) cube([3, 3, 0.4]);
}
