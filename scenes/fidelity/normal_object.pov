// povml fidelity scene: normal_object
// Rule: object pattern in a normal: two normals listed inside its block (the plane), and no list
// (the sphere): the slope of the 0/1 value, sampled around the point, bends the normal along the
// object's boundary.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
light_source { <-3, 6, -5> rgb 1 }
plane { y, 0
  pigment { rgb <0.8, 0.7, 0.5> }
  normal { object { cylinder { <0, -1, 0>, <0, 1, 0>, 1.4 } normal { bumps 0.8 scale 0.1 }, normal { gradient x 0.6 scale 0.3 } } rotate <0, 20, 0> }
  finish { ambient 0.1 diffuse 0.8 } }
sphere { <0, 1, 0>, 1
  pigment { rgb <0.3, 0.6, 1> }
  normal { object { box { <-0.3, -2, -2>, <0.3, 2, 2> } } 2 scale <1, 1, 1> }
  finish { ambient 0.1 diffuse 0.8 phong 0.5 } }
