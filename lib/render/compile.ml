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

let surface ~legacy ~ambient_light (t : Scene.texture) =
  let (Scene.Solid c) = t.pigment in
  let f = t.finish in
  let colour = Colour.rgb c in
  (* §3.2: the legacy "att" formula applies below language version 3.70 *)
  let att =
    if legacy then 1. -. ((c.filter *. Rgb.max3 colour) +. c.transmit) else 1. -. c.filter -. c.transmit
  in
  let emitted =
    Rgb.add
      (Rgb.scale att (Rgb.mul (Rgb.mul colour f.ambient) ambient_light))
      (Rgb.scale att (Rgb.mul colour f.emission))
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
    spec_exp = (if f.roughness = 0. then 0. else 1. /. f.roughness);
    metallic = f.metallic;
    refl = r;
    reflects = not (Rgb.is_zero r.rmin && Rgb.is_zero r.rmax);
    filcol = Colour.transmitted c;
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
             ior = o.interior.ior;
             fade_distance = o.interior.fade_distance;
             fade_power = o.interior.fade_power;
             fade_colour = o.interior.fade_colour;
             old_refract = o.texture.finish.refraction;
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
             lcolour = l.colour;
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
