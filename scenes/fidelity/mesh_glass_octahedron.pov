// povml fidelity scene: mesh_glass_octahedron
// Rule: refraction through a closed mesh: every triangle hit toggles the interior list, so the ray
//       enters (ior 1/1.5) at the front face and leaves (1.5/1) at a back face; transmitted colour is
//       scaled by filCol; inside_vector makes the mesh a solid whose Inside() counts triangle hits along
//       it (docs/povray-rules.md §2.6, §6.2, §6.3, §6.4); flat faces use the geometric normal flipped toward
//       the ray (§2.4, §3.1), including the back faces hit from inside.
// A glass octahedron (8 flat triangles, tilted, vertices given directly) in front of red, green and
// blue balls and a yellow backdrop: each facet shows a differently displaced, faceted view of them,
// with phong glints on the facets facing the light; its shadow on the floor is filtered (§4).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.43, 1.95, -6.2> look_at <0.02, 1.15, 0> right x*image_width/image_height angle 50 }
background { rgb <0.5, 0.6, 0.8> }
light_source { <-3.4, 6.1, -5.3>, rgb 1 }
#declare XP = <0.9178, 1.4649, -1.5588>;
#declare XM = <-0.9178, 1.0351, -0.2412>;
#declare YP = <-0.0125, 2.3483, -0.5591>;
#declare YM = <0.0125, 0.1517, -1.2409>;
#declare ZP = <0.6928, 0.9851, -0.0212>;
#declare ZM = <-0.6928, 1.5149, -1.7788>;
mesh {
  triangle { XP, YP, ZP }
  triangle { XP, YP, ZM }
  triangle { XP, YM, ZP }
  triangle { XP, YM, ZM }
  triangle { XM, YP, ZP }
  triangle { XM, YP, ZM }
  triangle { XM, YM, ZP }
  triangle { XM, YM, ZM }
  inside_vector <0, 0, 1>
  pigment { rgbf <0.95, 1, 0.95, 0.92> }
  finish { ambient 0 diffuse 0.08 phong 0.8 phong_size 90 }
  interior { ior 1.5 }
}
sphere { <-1.3, 0.55, 2.1>, 0.55 pigment { rgb <0.9, 0.2, 0.15> } }
sphere { < 0.15, 1.75, 2.6>, 0.6 pigment { rgb <0.2, 0.8, 0.25> } }
sphere { < 1.45, 0.5, 1.9>, 0.5 pigment { rgb <0.2, 0.3, 0.95> } }
plane { z, 4.5 pigment { rgb <0.95, 0.85, 0.35> } }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } }
