(* POV-Ray's defaults for reflection, finishes, textures and interiors (docs/povray-rules.md §10). *)

open Scene

let reflection =
  { rmin = Rgb.black; rmax = Rgb.black; fresnel = false; falloff = 1.; exponent = 1.; refl_metallic = 0. }

let finish =
  {
    ambient = Rgb.grey 0.1;
    emission = Rgb.black;
    diffuse = 0.6;
    brilliance = 1.;
    phong = 0.;
    phong_size = 40.;
    specular = 0.;
    roughness = 0.05;
    metallic = 0.;
    reflection;
    conserve_energy = false;
    refraction = 1.;
    legacy_ior = None;
    legacy_caustics = None;
    irid = 0.;
    irid_thickness = 0.;
    irid_turb = 0.;
    crand = 0.;
  }

let layer = { pigment = Solid Colour.black; normal = None; finish }
let texture = Layers [ layer ]
let interior = { ior = 1.; fade_distance = 0.; fade_power = 0.; fade_colour = Rgb.black; caustics = 0. }
