(* Pigment patterns and colour maps, after docs/povray-rules.md §17. *)

let checker = Patterns.checker
let gradient = Patterns.gradient
let hexagon = Patterns.hexagon
let brick = Patterns.brick

let two_pi = 2. *. Float.pi

(* sin(2π·frac v) as POV-Ray computes it, the fraction scaled by 50000 and back first (v ≥ 0 here,
   after the wrap of §17.1) *)
let cycloidal v = sin (((v -. floor v) *. 50000.) /. 50000. *. two_pi)

let shape_value ~frequency ~phase (w : Scene.wave) v =
  (* §17.1: C fmod with the modulus 1.00001, not 1 *)
  let v = if frequency <> 0. then Float.rem ((v *. frequency) +. phase) 1.00001 else v in
  let v = if v < 0. then v -. floor v else v in
  match w with
  | Ramp -> v
  | Triangle_wave ->
      let f = v -. floor v in
      if f < 0.5 then 2. *. f else 2. *. (1. -. f)
  | Sine_wave -> (1. +. cycloidal v) *. 0.5
  | Scallop_wave -> Float.abs (cycloidal (v *. 0.5))
  | Cubic_wave -> v *. v *. (3. -. (2. *. v))
  | Poly_wave e -> Float.pow v e

(* §17.2: entries are searched in the order written; colour channels are single precision *)
let lookup (map : Scene.map_entry array) v =
  let n = Array.length map in
  let last = map.(n - 1) in
  if v >= last.value then last.colour
  else
    let rec search (prev : Scene.map_entry) i =
      let cur = map.(i) in
      if v > cur.value then search cur (i + 1) else (prev, cur)
    in
    let prev, cur = search map.(0) 0 in
    if v = cur.value || prev == cur then cur.colour
    else
      let f = (v -. prev.value) /. (cur.value -. prev.value) in
      let mix a b = Precision.(f32 (a +. f32 (f *. f32 (b -. a)))) in
      let p = prev.colour and c = cur.colour in
      {
        Colour.red = mix p.red c.red;
        green = mix p.green c.green;
        blue = mix p.blue c.blue;
        filter = mix p.filter c.filter;
        transmit = mix p.transmit c.transmit;
      }

let f32_colour (c : Colour.t) =
  Precision.{ Colour.red = f32 c.red; green = f32 c.green; blue = f32 c.blue; filter = f32 c.filter; transmit = f32 c.transmit }

(* §17.2 for a pigment map: the same search; the entries' pigments are evaluated at the point the
   outer pattern saw (its warps applied), each through its own warps, and their colours blended.
   Each result carries Compute_Pigment's "colour found": false only for a point off a [once]
   image_map, and for a blend of two entries neither of which found one. *)
let rec at_pattern_point gen (p : Scene.patterned) hit q =
  match p.pattern with Average -> (average gen p hit q, true) | _ ->
  let g = if p.noise_generator = 0 then gen else p.noise_generator in
  let v = shape_value ~frequency:p.frequency ~phase:p.phase p.wave (Patterns.value_with ~frequency:p.frequency ~phase:p.phase p.pattern p.warps g hit q) in
  if Array.length p.pigments = 0 then (lookup p.map v, true)
  else
    let map = p.pigments in
    let n = Array.length map in
    let last = map.(n - 1) in
    if v >= last.pvalue then inner gen last.pigment hit q
    else
      let rec search (prev : Scene.pigment_entry) i =
        let cur = map.(i) in
        if v > cur.pvalue then search cur (i + 1) else (prev, cur)
      in
      let prev, cur = search map.(0) 0 in
      if v = cur.pvalue || prev == cur then inner gen cur.pigment hit q
      else
        let f = (v -. prev.pvalue) /. (cur.pvalue -. prev.pvalue) in
        let mix a b = Precision.(f32 (a +. f32 (f *. f32 (b -. a)))) in
        let c, found_c = inner gen cur.pigment hit q in
        let p, found_p = inner gen prev.pigment hit q in
        ( {
            Colour.red = mix p.red c.red;
            green = mix p.green c.green;
            blue = mix p.blue c.blue;
            filter = mix p.filter c.filter;
            transmit = mix p.transmit c.transmit;
          },
          found_c || found_p )

(* Do_Average_Pigments: the entries' colours weighed by their values and divided by the values'
   sum, all in single precision as POV-Ray's colours are *)
and average gen (p : Scene.patterned) hit q =
  let f = Precision.f32 in
  let r = ref 0. and g = ref 0. and b = ref 0. and fl = ref 0. and t = ref 0. and total = ref 0. in
  Array.iter
    (fun (e : Scene.pigment_entry) ->
      let c, _ = inner gen e.pigment hit q in
      let w = e.pvalue in
      let add acc x = acc := f (!acc +. f (x *. w)) in
      add r c.red; add g c.green; add b c.blue; add fl c.filter; add t c.transmit;
      total := f (!total +. w))
    p.pigments;
  let d x = f (x /. !total) in
  { Colour.red = d !r; green = d !g; blue = d !b; filter = d !fl; transmit = d !t }

and inner gen (pg : Scene.pigment) hit q =
  match pg with
  | Solid c | Solid_placed { colour = c; _ } -> (f32_colour c, true)
  | Pattern ({ pattern = Bitmap b; _ } as p) -> Image_map.colour b (warped p hit q)
  | Pattern p -> at_pattern_point gen p hit (warped p hit q)

(* Warp_EPoint: the warps, then the clamp of every coordinate to ±1e17, even without warps. A
   uv-mapped pigment starts from the hit's (u, v, 0) instead of the point it is given (pigment.cpp's
   UV_MAP_PATTERN case: the point is not used) *)
and warped (p : Scene.patterned) (hit : Patterns.hit) q = Warp.point p.warps p.pattern (if p.uv_mapping then hit.uv else q)

(* Compute_Pigment: an image_map's colour comes from the image at the warped point, a pattern's
   from its map *)
let found gen (p : Scene.patterned) hit (x : Vec.t) =
  match p.pattern with Bitmap b -> Image_map.colour b (warped p hit x) | _ -> at_pattern_point gen p hit (warped p hit x)

let eval gen (p : Scene.patterned) hit (x : Vec.t) = fst (found gen p hit x)

let colour_found gen (p : Scene.pigment) hit x =
  match p with Solid c | Solid_placed { colour = c; _ } -> (c, true) | Pattern pp -> found gen pp hit x

let colour_at gen (p : Scene.pigment) hit x = match p with Solid c | Solid_placed { colour = c; _ } -> c | Pattern pp -> eval gen pp hit x

let rec may_miss (p : Scene.pigment) =
  match p with
  | Solid _ | Solid_placed _ -> false
  | Pattern { pattern = Bitmap b; _ } -> b.once
  | Pattern pp -> Array.exists (fun (e : Scene.pigment_entry) -> may_miss e.pigment) pp.pigments

let clear (c : Colour.t) = Float.abs c.filter <= Precision.epsilon && Float.abs c.transmit <= Precision.epsilon

let rec opaque (p : Scene.pigment) =
  match p with
  | Solid c | Solid_placed { colour = c; _ } -> clear c
  | Pattern { pattern = Bitmap b; _ } -> Image_map.opaque b
  | Pattern pp ->
      if Array.length pp.pigments = 0 then Array.for_all (fun (e : Scene.map_entry) -> clear e.colour) pp.map
      else Array.for_all (fun (e : Scene.pigment_entry) -> opaque e.pigment) pp.pigments

let rec uses_uv (p : Scene.pigment) =
  match p with
  | Solid _ | Solid_placed _ -> false
  | Pattern pp -> pp.uv_mapping || Array.exists (fun (e : Scene.pigment_entry) -> uses_uv e.pigment) pp.pigments

let rec normal_uses_uv (n : Scene.normal) =
  n.nuv_mapping
  || match n.nmap with Normal_map es -> Array.exists (fun (e : Scene.normal_entry) -> normal_uses_uv e.nnormal) es | No_map | Slope_map _ -> false

let f32_entry v (c : Colour.t) : Scene.map_entry =
  {
    value = Precision.f32 v;
    colour = f32_colour c;
  }

let rgb r g b = { Colour.black with red = r; green = g; blue = b }

let entries l = Array.of_list (List.map (fun (v, r, g, b) -> f32_entry v (rgb r g b)) l)

(* pigment.cpp's default maps; checker shares the hexagon's entries, square and triangular the
   cubic's, as POV-Ray's tables do *)
let hex_entries = entries [ (0., 0., 0., 1.); (1., 0., 1., 0.); (2., 1., 0., 0.) ]

let cubic_entries =
  entries [ (0., 1., 0., 0.); (1., 0., 1., 0.); (1., 0., 0., 1.); (1., 1., 1., 0.); (1., 0., 1., 1.); (2., 1., 0., 1.) ]

let grey_map = entries [ (0., 0., 0., 0.); (1., 1., 1., 1.) ]

let bozo_map =
  entries [ (0.4, 1., 1., 1.); (0.4, 0., 1., 0.); (0.6, 0., 1., 0.); (0.6, 0., 0., 1.); (0.8, 0., 0., 1.); (0.8, 1., 0., 0.) ]

let wood_map = entries [ (0.6, 0.666, 0.312, 0.2); (0.6, 0.4, 0.1333, 0.066) ]

let mandel_map =
  entries [ (0.001, 0., 0., 0.); (0.001, 0., 1., 1.); (0.012, 1., 1., 0.); (0.015, 1., 0., 1.); (0.1, 0., 1., 1.) ]

let agate_map =
  entries
    [ (0., 1., 1., 1.); (0.5, 0.95, 0.75, 0.5); (0.5, 0.9, 0.7, 0.5); (0.6, 0.9, 0.7, 0.4); (0.6, 1., 0.7, 0.4); (1., 0.6, 0.3, 0.) ]

let radial_map = entries [ (0., 0., 1., 1.); (0.333, 1., 1., 0.); (0.666, 1., 0., 1.); (1., 0., 1., 1.) ]
let marble_map = entries [ (0., 0.9, 0.8, 0.8); (0.9, 0.9, 0.08, 0.08); (0.9, 0., 0., 0.) ]
let brick_map = entries [ (0., 0.5, 0.5, 0.5); (1., 0.6, 0.15, 0.15) ]

let default_map (p : Scene.pattern) =
  match p with
  | Checker | Object_pattern _ -> Array.sub hex_entries 0 2 (* pigment.cpp: the object pattern has checker's map *)
  | Hexagon -> hex_entries
  | Brick _ -> brick_map
  | Square -> Array.sub cubic_entries 0 4
  | Triangular | Cubic -> cubic_entries
  | Bozo -> bozo_map
  | Wood -> wood_map
  | Fractal { fkind = Mandel; _ } -> mandel_map
  | Radial -> radial_map
  | Agate _ -> agate_map
  | Marble -> marble_map
  | _ -> grey_map
