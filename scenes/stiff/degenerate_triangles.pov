// povml stiff scene: degenerate_triangles
// Stresses: triangles at and near zero area. Zero-area triangles (three collinear corners, a
// repeated corner, all three corners equal, corners 1e-170 apart whose cross product underflows
// to zero) have no normal: POV-Ray warns "Degenerate triangle" and never hits them (§2.4), and a
// mesh drops them silently (§2.6); none may produce a NaN normal. Slivers keep a normal: a
// needle 3.5 long and at most 0.02 wide (half a pixel), a fan of 64 slivers 0.2 degrees wide
// each around one point, and a triangle whose corners are 1e-4 apart (its unit normal comes
// from a cross product of size 1e-8). The inside test projects along the dominant axis and
// uses `<` on the edges (§2.4), so on an edge shared by two slivers a ray may hit both.
// A correct image: a dotted dark line (the needle, hit by a pixel ray here and there) across
// the red triangle, the fan as a solid pale sector, a black dot for the tiny triangle, nothing
// at all for the zero-area ones, and the mesh (half of its faces degenerate) as a plain blue
// square; the shadows of the needle and the fan on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 1, 0> right x*image_width/image_height angle 55 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-3, 8, -6>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
#declare Pale = texture { pigment { rgb <0.95, 0.95, 0.9> } finish { ambient 0.3 diffuse 0.7 } }
// zero area: collinear, repeated corner, all equal, underflowing cross product
triangle { <-3, 0.5, 0>, <-2, 1, 0>, <-1, 1.5, 0> texture { Pale } }
triangle { <-3, 2, 0>, <-3, 2, 0>, <-2, 2.5, 0> texture { Pale } }
triangle { <-2.5, 1, -1>, <-2.5, 1, -1>, <-2.5, 1, -1> texture { Pale } }
triangle { <-2, 2, -0.5>, <-2, 2, -0.5> + <1e-170, 0, 0>, <-2, 2, -0.5> + <0, 1e-170, 0> texture { Pale } }
// a red backdrop triangle with a needle in front of it, at most 0.02 wide (half a pixel)
triangle { <-3.2, 0, 1.5>, <-0.4, 0, 1.5>, <-1.8, 2.8, 1.5> pigment { rgb <0.9, 0.2, 0.15> } }
triangle { <-3.1, 0.3, 1>, <-0.5, 2.6, 1>, <-0.5, 2.62, 1> pigment { rgb 0.3 } }
// a fan of 64 slivers, 0.2 degrees each, about <1.2, 1.4, 0.5>
#declare I = 0;
#while (I < 64)
  triangle { <1.2, 1.4, 0.5>,
             <1.2, 1.4, 0.5> + 1.4 * <cos(radians(20 + I * 0.2)), sin(radians(20 + I * 0.2)), 0>,
             <1.2, 1.4, 0.5> + 1.4 * <cos(radians(20 + (I + 1) * 0.2)), sin(radians(20 + (I + 1) * 0.2)), 0>
             texture { Pale } }
  #declare I = I + 1;
#end
// a triangle 1e-4 across
triangle { <0.3, 0.8, -1>, <0.3001, 0.8, -1>, <0.3, 0.8001, -1> pigment { rgb <0, 0, 0> } finish { ambient 1 } }
// a mesh with degenerate faces mixed in
mesh {
  triangle { <1, 0.01, -1.5>, <2, 0.01, -1.5>, <2, 0.01, -0.5> }
  triangle { <1, 0.01, -1.5>, <1, 0.01, -1.5>, <2, 0.01, -0.5> }
  triangle { <1, 0.01, -1.5>, <2, 0.01, -0.5>, <1, 0.01, -0.5> }
  triangle { <1, 0.01, -1.5>, <1.5, 0.01, -1>, <2, 0.01, -0.5> }
  pigment { rgb <0.2, 0.3, 0.9> }
}
