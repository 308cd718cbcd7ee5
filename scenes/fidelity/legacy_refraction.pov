// povml fidelity scene: legacy_refraction
// Rule: legacy (no #version) `finish { refraction R ior I }`: ior is copied into the interior and
//       Old_Refract = R scales the transmitted colour (attCol) (docs/povray-rules.md §2.7, §6.3);
//       no #version also means gamma off and the legacy att formula (§8.1, §8.2).
// Left: finish { refraction 1 ior 1.33 } (water ball). Right: finish { refraction 0.5 ior 1.5 }
// (transmitted light halved). POV-Ray may warn that these finish keywords are deprecated.
camera { location <0, 1.3, -6> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.5, 0.6, 0.8> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-1.2, 1.0, -1>, 0.9 pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.8 refraction 1 ior 1.33 } }
sphere { < 1.2, 1.0, -1>, 0.9 pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.8 refraction 0.5 ior 1.5 } }
sphere { <-1.5, 0.6, 2.5>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { < 0.0, 1.6, 2.5>, 0.5 pigment { rgb <0.2, 0.8, 0.2> } }
sphere { < 1.5, 0.6, 2.5>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } }
plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } }
