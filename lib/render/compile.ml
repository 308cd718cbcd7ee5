open Compiled

let epsilon = 1e-10

let shape_of (s : Scene.shape) =
  match s with
  | Sphere { centre; radius } -> Sphere { cx = centre.x; cy = centre.y; cz = centre.z; radius; r2 = radius *. radius }
  | Plane { normal; offset } -> Plane { nx = normal.x; ny = normal.y; nz = normal.z; dist = -.offset }

let inside shape (p : Vec.t) =
  match shape with
  | Sphere s ->
      let dx = p.x -. s.cx and dy = p.y -. s.cy and dz = p.z -. s.cz in
      (dx *. dx) +. (dy *. dy) +. (dz *. dz) < s.r2
  | Plane pl -> (p.x *. pl.nx) +. (p.y *. pl.ny) +. (p.z *. pl.nz) +. pl.dist < epsilon

(* POV-Ray stores colours in single precision (§8.3); rounding the stored values the same way keeps
   results on the same side of the 8-bit rounding boundaries. *)
let f32 x = Int32.float_of_bits (Int32.bits_of_float x)
let rgb32 (c : Rgb.t) = Rgb.make (f32 c.r) (f32 c.g) (f32 c.b)

let colour32 (c : Colour.t) =
  { Colour.red = f32 c.red; green = f32 c.green; blue = f32 c.blue; filter = f32 c.filter; transmit = f32 c.transmit }

let reflection32 (r : Scene.reflection) =
  { r with rmin = rgb32 r.rmin; rmax = rgb32 r.rmax; falloff = f32 r.falloff; refl_metallic = f32 r.refl_metallic }

let surface ~legacy ~ambient_light (t : Scene.texture) =
  let (Scene.Solid c) = t.pigment in
  let c = colour32 c in
  let f0 = t.finish in
  (* finish scalars are single precision too *)
  let f =
    {
      f0 with
      ambient = rgb32 f0.ambient;
      emission = rgb32 f0.emission;
      reflection = reflection32 f0.reflection;
      diffuse = f32 f0.diffuse;
      brilliance = f32 f0.brilliance;
      phong = f32 f0.phong;
      phong_size = f32 f0.phong_size;
      specular = f32 f0.specular;
      metallic = f32 f0.metallic;
    }
  in
  let ambient_light = rgb32 ambient_light in
  let colour = Colour.rgb c in
  (* §3.2: the legacy "att" formula applies below language version 3.70 *)
  let att =
    if legacy then 1. -. ((c.filter *. Rgb.max3 colour) +. c.transmit) else 1. -. c.filter -. c.transmit
  in
  (* §3.2, in single precision as POV-Ray sums it: ((C·ambient)·ambient_light)·att, then + (C·emission)·att *)
  let mul a b = f32 (a *. b) in
  let term c a l = mul (mul (mul c a) l) att in
  let emitted =
    Rgb.make
      (f32 (term colour.r f.ambient.r ambient_light.r +. mul (mul colour.r f.emission.r) att))
      (f32 (term colour.g f.ambient.g ambient_light.g +. mul (mul colour.g f.emission.g) att))
      (f32 (term colour.b f.ambient.b ambient_light.b +. mul (mul colour.b f.emission.b) att))
  in
  let r = f.reflection in
  {
    colour;
    att;
    emitted;
    lit = f.diffuse <> 0. || f.phong <> 0. || f.specular <> 0.;
    diffuse = f.diffuse;
    brilliance = f.brilliance;
    phong = f.phong;
    phong_size = f.phong_size;
    specular = f.specular;
    spec_exp = (if f.roughness = 0. then 0. else f32 (1. /. f.roughness));
    metallic = f.metallic;
    refl = r;
    reflects = not (Rgb.is_zero r.rmin && Rgb.is_zero r.rmax);
    filcol = Rgb.make (f32 (f32 (c.red *. c.filter) +. c.transmit)) (f32 (f32 (c.green *. c.filter) +. c.transmit)) (f32 (f32 (c.blue *. c.filter) +. c.transmit));
    transparent = c.filter <> 0. || c.transmit <> 0.;
    conserve = f.conserve_energy;
  }

let scene (s : Scene.t) : Compiled.t =
  let legacy = s.version < 370 in
  let objects =
    Array.of_list
      (List.mapi
         (fun id (o : Scene.obj) ->
           let surf = surface ~legacy ~ambient_light:s.ambient_light o.texture in
           {
             id;
             shape = shape_of o.shape;
             surf;
             ior = f32 o.interior.ior;
             fade_distance = f32 o.interior.fade_distance;
             fade_power = f32 o.interior.fade_power;
             fade_colour = rgb32 o.interior.fade_colour;
             old_refract = f32 o.texture.finish.refraction;
             opaque = not surf.transparent;
           })
         s.objects)
  in
  let casts = Array.of_list (List.map (fun (o : Scene.obj) -> not o.no_shadow) s.objects) in
  let occluders = Array.of_list (List.filter (fun (o : obj) -> casts.(o.id)) (Array.to_list objects)) in
  let shadow_mode =
    if Array.length occluders = 0 then No_occluders
    else if Array.for_all (fun o -> o.opaque) occluders then Any_hit
    else Filtered
  in
  let lights =
    Array.of_list
      (List.map
         (fun (l : Scene.light) ->
           {
             lx = l.position.x;
             ly = l.position.y;
             lz = l.position.z;
             lcolour = rgb32 l.colour;
             shadowless = l.shadowless;
             fade = l.fade_power > 0. && Float.abs l.fade_distance > epsilon;
             lfade_distance = l.fade_distance;
             lfade_power = l.fade_power;
           })
         s.lights)
  in
  (* §6.4: the camera ray starts inside every object that contains the camera location; the list
     is kept with the last entered first. *)
  let start_interiors =
    Array.fold_left (fun acc o -> if inside o.shape s.camera.location then o.id :: acc else acc) [] objects
  in
  {
    objects;
    occluders;
    shadow_mode;
    lights;
    background = s.background;
    sky = s.sky;
    max_trace_level = s.max_trace_level;
    adc_bailout = s.adc_bailout;
    legacy;
    camera = s.camera;
    start_interiors;
  }
