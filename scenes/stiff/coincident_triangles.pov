// povml stiff scene: coincident_triangles
// Stresses: coplanar and coincident surfaces, where the nearest hit is decided by rounding or by
// a tie. Left: a red and a green triangle with the same three corners (equal depths: the first
// one met in the bounding order wins, §2.1, §13.22). Middle: two overlapping coplanar triangles
// with different corners (their depths differ only by rounding, so the winner changes from
// pixel to pixel: z-fighting). Right: a mesh holding the same face twice and a standalone
// triangle in the mesh's plane. Front: a triangle lying in the floor plane.
// A correct image: whatever POV-Ray shows, pixel for pixel; such ties are decided by the order
// of the objects in the bounding hierarchy and by the last bit of the depth, not by anything in
// the scene description. Physically there is no right answer.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6> look_at <0, 1, 0> right x*image_width/image_height angle 55 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-3, 8, -6>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
// identical corners
triangle { <-3.2, 0.2, 0.5>, <-1.2, 0.4, 0.3>, <-2.3, 2.4, 0.6> pigment { rgb <0.9, 0.2, 0.15> } }
triangle { <-3.2, 0.2, 0.5>, <-1.2, 0.4, 0.3>, <-2.3, 2.4, 0.6> pigment { rgb <0.2, 0.8, 0.3> } }
// overlapping, coplanar (plane z = 0.1 x + 0.05 y + 0.4), different corners
#macro Z(X, Y) (0.1 * X + 0.05 * Y + 0.4) #end
triangle { <-0.9, 0.2, Z(-0.9, 0.2)>, <0.9, 0.3, Z(0.9, 0.3)>, <0, 2.3, Z(0, 2.3)> pigment { rgb <0.9, 0.8, 0.2> } }
triangle { <-0.7, 2.1, Z(-0.7, 2.1)>, <0.8, 1.9, Z(0.8, 1.9)>, <0.1, 0.1, Z(0.1, 0.1)> pigment { rgb <0.2, 0.4, 0.9> } }
// mesh with a duplicated face, plus a standalone triangle in its plane
mesh {
  triangle { <1.3, 0.2, 0.2>, <3.2, 0.2, 0.6>, <2.2, 2.3, 0.4> }
  triangle { <1.3, 0.2, 0.2>, <3.2, 0.2, 0.6>, <2.2, 2.3, 0.4> }
  pigment { rgb <0.7, 0.3, 0.8> }
}
triangle { <1.6, 1.2, 0.3>, <3.0, 1.0, 0.5619047619047619>, <2.0, 0.4, 0.3> pigment { rgb <0.95, 0.95, 0.9> } }
// a triangle in the floor plane
triangle { <-1.5, 0, -2.5>, <1.5, 0, -2.5>, <0, 0, -1> pigment { rgb <0.3, 0.3, 0.3> } }
