(* The evaluated scene as text (povml --dump): what the interpreter made of the scene after every
   directive, macro and loop, in a POV-Ray-like notation. Numbers are printed with up to 10
   significant digits, so the output is stable across runs and readable in tests. *)

open Scene

let num x =
  let x = if x = 0. then 0. else x (* no "-0" *) in
  if Float.is_integer x && Float.abs x < 1e15 then Printf.sprintf "%.0f" x
  else if Float.is_nan x then "nan"
  else if x = Float.infinity then "inf"
  else if x = Float.neg_infinity then "-inf"
  else Printf.sprintf "%.10g" x

let vec (v : Vec.t) = Printf.sprintf "<%s, %s, %s>" (num v.x) (num v.y) (num v.z)
let rgb (c : Rgb.t) = Printf.sprintf "rgb <%s, %s, %s>" (num c.r) (num c.g) (num c.b)

let colour (c : Colour.t) =
  if c.filter = 0. && c.transmit = 0. then Printf.sprintf "rgb <%s, %s, %s>" (num c.red) (num c.green) (num c.blue)
  else Printf.sprintf "rgbft <%s, %s, %s, %s, %s>" (num c.red) (num c.green) (num c.blue) (num c.filter) (num c.transmit)

let matrix (t : Transform.t) =
  Printf.sprintf "matrix <%s>"
    (String.concat ", "
       (List.map num [ t.m00; t.m01; t.m02; t.m10; t.m11; t.m12; t.m20; t.m21; t.m22; t.m30; t.m31; t.m32 ]))

(* Only what differs from the default finish (docs/povray-rules.md §10.1) is shown. *)
let finish (f : finish) =
  let d = Defaults.finish in
  let items = ref [] in
  let add cond s = if cond then items := s :: !items in
  add (f.ambient <> d.ambient) ("ambient " ^ rgb f.ambient);
  add (f.emission <> d.emission) ("emission " ^ rgb f.emission);
  add (f.diffuse <> d.diffuse) ("diffuse " ^ num f.diffuse);
  add (f.brilliance <> d.brilliance) ("brilliance " ^ num f.brilliance);
  add (f.phong <> d.phong) ("phong " ^ num f.phong);
  add (f.phong_size <> d.phong_size) ("phong_size " ^ num f.phong_size);
  add (f.specular <> d.specular) ("specular " ^ num f.specular);
  add (f.roughness <> d.roughness) ("roughness " ^ num f.roughness);
  add (f.metallic <> d.metallic) ("metallic " ^ num f.metallic);
  let r = f.reflection in
  if r <> d.reflection then
    add true
      (Printf.sprintf "reflection { %s, %s%s falloff %s exponent %s metallic %s }" (rgb r.rmin) (rgb r.rmax)
         (if r.fresnel then " fresnel" else "") (num r.falloff) (num r.exponent) (num r.refl_metallic));
  add f.conserve_energy "conserve_energy";
  add (f.refraction <> d.refraction) ("refraction " ^ num f.refraction);
  (match f.legacy_ior with Some i -> add true ("ior " ^ num i) | None -> ());
  (match f.legacy_caustics with Some c -> add true ("caustics " ^ num c) | None -> ());
  add (f.crand <> 0.) ("crand " ^ num f.crand);
  add (f.irid <> 0.) (Printf.sprintf "irid { %s thickness %s turbulence %s }" (num f.irid) (num f.irid_thickness) (num f.irid_turb));
  String.concat " " (List.rev !items)

(* The other patterns by their keyword and main values. *)
(* An image's file and settings, as image_map, bump_map and image_pattern were written. *)
let bitmap (b : bitmap) =
  let use = match b.use with Use_none -> " use_index" | Use_colour -> "" | Use_index -> " use_index" | Use_alpha -> " use_alpha" in
  Printf.sprintf "\"%s\" %dx%d map_type %d interpolate %d%s%s repeat <%s, %s> offset <%s, %s> filter all %s transmit all %s" b.file
    b.image.width b.image.height b.map_type b.interpolate (if b.once then " once" else "") use (num b.width) (num b.height)
    (num b.offset_u) (num b.offset_v) (num b.all_filter) (num b.all_transmit)

let pattern_name (p : pattern) =
  match p with
  | Checker -> "checker"
  | Gradient v -> "gradient " ^ vec v
  | Hexagon -> "hexagon"
  | Brick _ -> "brick"
  | Square -> "square"
  | Triangular -> "triangular"
  | Cubic -> "cubic"
  | Agate t -> "agate agate_turb " ^ num t
  | Bozo -> "bozo"
  | Spotted -> "spotted"
  | Bumps -> "bumps"
  | Granite -> "granite"
  | Leopard -> "leopard"
  | Marble -> "marble"
  | Wood -> "wood"
  | Onion -> "onion"
  | Radial -> "radial"
  | Cells -> "cells"
  | Crackle { form; metric; offset; solid } ->
      Printf.sprintf "crackle form %s metric %s offset %s%s" (vec form) (num metric) (num offset) (if solid then " solid" else "")
  | Wrinkles -> "wrinkles"
  | Dents -> "dents"
  | Waves n -> if n = 10 then "waves" else Printf.sprintf "waves (number_of_waves %d)" n
  | Ripples n -> if n = 10 then "ripples" else Printf.sprintf "ripples (number_of_waves %d)" n
  | Quilted { control0; control1 } -> Printf.sprintf "quilted control0 %s control1 %s" (num control0) (num control1)
  | Facets { fsize; coords; fmetric } ->
      Printf.sprintf "facets%s size %s metric %s" (if coords <> 0. then " coords " ^ num coords else "") (num fsize) (num fmetric)
  | Spiral1 n -> Printf.sprintf "spiral1 %d" n
  | Spiral2 n -> Printf.sprintf "spiral2 %d" n
  | Planar -> "planar"
  | Boxed -> "boxed"
  | Spherical -> "spherical"
  | Cylindrical -> "cylindrical"
  | Fractal f ->
      let kind =
        match f.fkind with
        | Mandel -> "mandel"
        | Julia (a, b) -> Printf.sprintf "julia <%s, %s>" (num a) (num b)
        | Magnet_mandel n -> Printf.sprintf "magnet %d mandel" n
        | Magnet_julia (n, (a, b)) -> Printf.sprintf "magnet %d julia <%s, %s>" n (num a) (num b)
      in
      Printf.sprintf "%s %d exponent %d interior %d, %s exterior %d, %s" kind f.iterations f.exponent f.interior_type
        (num f.ifactor) f.exterior_type (num f.efactor)
  | Pavement v ->
      Printf.sprintf "pavement number_of_sides %d number_of_tiles %d pattern %d exterior %d interior %d form %d" v.side
        v.tile v.number v.exterior v.interior v.form
  | Tiling n -> Printf.sprintf "tiling %d" n
  | Aoi -> "aoi"
  | Slope s -> "slope " ^ vec s.slope_vector
  | Average -> "average"
  | Object_pattern t -> "object { " ^ t.shown ^ " }"
  | Pigment_pattern p -> "pigment_pattern { " ^ p.pshown ^ " }"
  | No_pattern -> "(no pattern)"
  | Bitmap b -> "image_map { " ^ bitmap b ^ " }"
  | Image_pattern b -> "image_pattern { " ^ bitmap b ^ " }"
  | Function_pattern f -> if f.Fn.name = "" then "function { … }" else Printf.sprintf "function { %s(x, y, z) }" f.Fn.name

let turb (t : turb) =
  Printf.sprintf "turbulence %s octaves %d omega %s lambda %s" (vec t.turbulence) t.octaves (num t.omega) (num t.lambda)

let warp (w : warp) =
  match w with
  | Transform_warp t -> matrix t
  | Classic_turb t -> turb t
  | Turb_warp t -> "warp { " ^ turb t ^ " }"
  | Repeat_warp r -> Printf.sprintf "warp { repeat axis %d width %s offset %s flip %s }" r.axis (num r.width) (vec r.offset) (vec r.flip)
  | Black_hole b -> Printf.sprintf "warp { black_hole %s, %s strength %s falloff %s }" (vec b.centre) (num b.radius) (num b.strength) (num b.power)
  | Cylindrical_warp c -> Printf.sprintf "warp { cylindrical orientation %s dist_exp %s }" (vec c.orientation) (num c.dist_exp)
  | Spherical_warp c -> Printf.sprintf "warp { spherical orientation %s dist_exp %s }" (vec c.orientation) (num c.dist_exp)
  | Toroidal_warp c ->
      Printf.sprintf "warp { toroidal orientation %s dist_exp %s major_radius %s }" (vec c.orientation) (num c.dist_exp) (num c.major_radius)
  | Planar_warp c -> Printf.sprintf "warp { planar %s, %s }" (vec c.orientation) (num c.offset)
  | Cubic_warp -> "warp { cubic }"

(* A pattern pigment with its whole map and its composed transform (docs/povray-rules.md §17). *)
let rec pigment = function
  | Solid c | Solid_placed { colour = c; _ } -> colour c
  | Pattern p ->
      let pat =
        match p.pattern with
        | Checker -> "checker"
        | Gradient v -> "gradient " ^ vec v
        | Hexagon -> "hexagon"
        | Brick { size; mortar } -> Printf.sprintf "brick brick_size %s mortar %s" (vec size) (num mortar)
        | other -> pattern_name other
      in
      let wave =
        match p.wave with
        | Ramp -> ""
        | Triangle_wave -> " triangle_wave"
        | Sine_wave -> " sine_wave"
        | Scallop_wave -> " scallop_wave"
        | Cubic_wave -> " cubic_wave"
        | Poly_wave e -> " poly_wave " ^ num e
      in
      let map =
        if Array.length p.pigments = 0 then
          let entries = Array.to_list (Array.map (fun (e : map_entry) -> Printf.sprintf "[%s %s]" (num e.value) (colour e.colour)) p.map) in
          Printf.sprintf "color_map { %s }" (String.concat " " entries)
        else
          let entries = Array.to_list (Array.map (fun (e : pigment_entry) -> Printf.sprintf "[%s %s]" (num e.pvalue) (pigment e.pigment)) p.pigments) in
          Printf.sprintf "pigment_map { %s }" (String.concat " " entries)
      in
      Printf.sprintf "%s%s frequency %s phase %s%s %s%s" (if p.uv_mapping then "uv_mapping " else "") pat (num p.frequency) (num p.phase) wave map
        (String.concat "" (List.rev_map (fun w -> " " ^ warp w) p.warps))

let wave_name (w : wave) =
  match w with
  | Ramp -> ""
  | Triangle_wave -> " triangle_wave"
  | Sine_wave -> " sine_wave"
  | Scallop_wave -> " scallop_wave"
  | Cubic_wave -> " cubic_wave"
  | Poly_wave e -> " poly_wave " ^ num e

(* A normal with its amount, accuracy, map and warps. *)
let rec normal (n : normal) =
  let map =
    match n.nmap with
    | No_map -> ""
    | Slope_map es ->
        Printf.sprintf " slope_map { %s }"
          (String.concat " " (Array.to_list (Array.map (fun (e : slope_entry) -> Printf.sprintf "[%s <%s, %s>]" (num e.svalue) (num e.height) (num e.slope)) es)))
    | Normal_map es ->
        Printf.sprintf " normal_map { %s }"
          (String.concat " " (Array.to_list (Array.map (fun (e : normal_entry) -> Printf.sprintf "[%s %s]" (num e.nvalue) (normal e.nnormal)) es)))
  in
  Printf.sprintf "%s%s %s accuracy %s frequency %s phase %s%s%s%s%s" (if n.nuv_mapping then "uv_mapping " else "") (pattern_name n.npattern) (num n.amount) (num n.accuracy)
    (num n.nfrequency) (num n.nphase) (wave_name n.nwave)
    (if n.no_bump_scale then " no_bump_scale" else "")
    map
    (String.concat "" (List.rev_map (fun w -> " " ^ warp w) n.nwarps))

let layer (t : layer) =
  let f = finish t.finish in
  Printf.sprintf "texture { pigment { %s }%s%s }" (pigment t.pigment)
    (match t.normal with None -> "" | Some n -> Printf.sprintf " normal { %s }" (normal n))
    (if f = "" then "" else Printf.sprintf " finish { %s }" f)

(* layers as written (the bottom first); a patterned texture as its pattern (shown as a pigment's,
   without the unused colour map) and its entries *)
let rec texture (t : texture) =
  match t with
  | Layers ls -> String.concat " " (List.rev_map layer ls)
  | Texture_pattern { tpat; tmap } ->
      let pat = pigment (Pattern { tpat with map = [| { value = 0.; colour = Colour.black } |]; pigments = [||] }) in
      let entries = Array.to_list (Array.map (fun e -> Printf.sprintf "[%s %s]" (num e.tvalue) (texture e.ttexture)) tmap) in
      Printf.sprintf "texture { %s texture_map { %s } }" pat (String.concat " " entries)
  | Material_map { mimage; mwarps; materials } ->
      Printf.sprintf "texture { material_map { %s %s }%s }" (bitmap mimage)
        (String.concat " " (Array.to_list (Array.map texture materials)))
        (String.concat "" (List.rev_map (fun w -> " " ^ warp w) mwarps))
  | Cutaway -> "texture { } // cutaway: the textures of the members around"
  | Uv_mapped { uwarps; inner } ->
      Printf.sprintf "texture { uv_mapping %s%s }" (texture inner) (String.concat "" (List.rev_map (fun w -> " " ^ warp w) uwarps))

let interior (i : interior) =
  if i = Defaults.interior then ""
  else
    Printf.sprintf "\n  interior { ior %s%s%s }" (num i.ior)
      (if i.fade_distance <> 0. || i.fade_power <> 0. then
         Printf.sprintf " fade_distance %s fade_power %s fade_color %s" (num i.fade_distance) (num i.fade_power) (rgb i.fade_colour)
       else "")
      (if i.caustics <> 0. then Printf.sprintf " caustics %s" (num (i.caustics /. 45.)) else "")

let trans = function None -> "" | Some t -> "\n  " ^ matrix t

let rec shape = function
  | Sphere { centre; radius; trans = t; _ } -> Printf.sprintf "sphere { %s, %s%s" (vec centre) (num radius) (trans t)
  | Plane { normal; offset; trans = t } -> Printf.sprintf "plane { %s, %s%s" (vec normal) (num offset) (trans t)
  | Triangle { p1; p2; p3 } -> Printf.sprintf "triangle { %s, %s, %s" (vec p1) (vec p2) (vec p3)
  | Smooth_triangle { p1; n1; p2; n2; p3; n3 } ->
      Printf.sprintf "smooth_triangle { %s, %s, %s, %s, %s, %s" (vec p1) (vec n1) (vec p2) (vec n2) (vec p3) (vec n3)
  | Box { lo; hi; trans = t } -> Printf.sprintf "box { %s, %s%s" (vec lo) (vec hi) (trans t)
  | Cone { p1; r1; p2; r2; cylinder; dist; closed; trans = t } ->
      let flags = if closed then "" else " open" in
      let canon = if cylinder then "canonical cylinder" else Printf.sprintf "canonical cone from z = %s" (num dist) in
      if r1 = r2 && cylinder then Printf.sprintf "cylinder { %s, %s, %s%s // %s%s" (vec p1) (vec p2) (num r1) flags canon (trans (Some t))
      else Printf.sprintf "cone { %s, %s, %s, %s%s // %s%s" (vec p1) (num r1) (vec p2) (num r2) flags canon (trans (Some t))
  | Disc { centre; normal; radius; hole; trans = t } ->
      Printf.sprintf "disc { %s, %s, %s, %s // centre as written, normal as moved%s" (vec centre) (vec normal) (num radius)
        (num hole) (trans (Some t))
  | Torus { major; minor; sturm; trans = t } ->
      Printf.sprintf "torus { %s, %s%s%s" (num major) (num minor) (if sturm then " sturm" else "")
        (trans (if Transform.is_identity t then None else Some t))
  | Glyph { outline; depth; trans = t } ->
      Printf.sprintf "glyph { // %d contours, %d segments, box <%d, %d> … <%d, %d> of %d units per em, depth %s%s" outline.contours
        outline.nseg outline.xmin outline.ymin outline.xmax outline.ymax outline.units_per_em (num depth) (trans (Some t))
  | Mesh { mesh; trans = t; textures } ->
      let b = Mesh.bounds mesh in
      Printf.sprintf "mesh { // %d triangles within <%s, %s, %s> … <%s, %s, %s>%s%s" mesh.faces (num b.(0)) (num b.(1))
        (num b.(2)) (num b.(3)) (num b.(4)) (num b.(5))
        (if Array.length textures > 0 then Printf.sprintf ", %d face textures" (Array.length textures) else "")
        (trans t)
  | Polygon { tr; points; degenerate } ->
      let n = Array.length points / 2 in
      let uv k = Printf.sprintf "<%s, %s>" (num points.(2 * k)) (num points.((2 * k) + 1)) in
      Printf.sprintf "polygon { %d, %s // the points in its own plane%s%s" n (String.concat ", " (List.init n uv))
        (if degenerate then ", degenerate: never hit" else "")
        (trans (Some tr))
  | Prism p ->
      let sp = match p.spline with Linear -> "linear_spline" | Quadratic -> "quadratic_spline" | Cubic -> "cubic_spline" | Bezier -> "bezier_spline" in
      Printf.sprintf "prism { %s %s %s, %s // %d segments within <%s, %s> … <%s, %s>%s%s%s%s" sp
        (if p.conic then "conic_sweep" else "linear_sweep") (num p.height1) (num p.height2) (Array.length p.segs) (num p.x1) (num p.y1)
        (num p.x2) (num p.y2) (if p.closed then "" else " open") (if p.sturm then " sturm" else "")
        (if p.degenerate then ", not closed: never hit" else "")
        (trans (if Transform.is_identity p.tr then None else Some p.tr))
  | Lathe l ->
      let sp = match l.spline with Linear -> "linear_spline" | Quadratic -> "quadratic_spline" | Cubic -> "cubic_spline" | Bezier -> "bezier_spline" in
      Printf.sprintf "lathe { %s // %d segments, radius %s … %s, height %s … %s%s%s" sp (Array.length l.segs) (num l.radius1) (num l.radius2)
        (num l.height1) (num l.height2) (if l.sturm then " sturm" else "")
        (trans (if Transform.is_identity l.tr then None else Some l.tr))
  | Sor s ->
      Printf.sprintf "sor { // %d segments, radius %s … %s, height %s … %s%s%s%s" (Array.length s.segs) (num s.radius1) (num s.radius2)
        (num s.height1) (num s.height2) (if s.closed then "" else " open") (if s.sturm then " sturm" else "")
        (trans (if Transform.is_identity s.tr then None else Some s.tr))
  | Poly { order; coeffs; sturm; tr } ->
      Printf.sprintf "poly { %d, <%s>%s%s" order (String.concat ", " (Array.to_list (Array.map num coeffs)))
        (if sturm then " sturm" else "") (trans (Some tr))
  | Quadric q ->
      Printf.sprintf "quadric { <%s, %s, %s>, <%s, %s, %s>, <%s, %s, %s>, %s // box <%s, %s, %s> + <%s, %s, %s>" (num q.xx)
        (num q.yy) (num q.zz) (num q.xy) (num q.xz) (num q.yz) (num q.lx) (num q.ly) (num q.lz) (num q.k) (num q.box_llx)
        (num q.box_lly) (num q.box_llz) (num q.box_lenx) (num q.box_leny) (num q.box_lenz)
  | Blob { blob; textures } ->
      Printf.sprintf "%s%s%s" (Blob.describe num vec matrix blob)
        (if Array.length textures > 0 then Printf.sprintf "\n  // %d component textures" (Array.length textures) else "")
        (trans blob.trans)
  | Height_field { field = f; trans = t } ->
      Printf.sprintf "height_field { // %d x %d heights %d … %d, box y %s … %s%s%s%s%s" f.width f.height f.min_y f.max_y (num f.lo_y)
        (num f.hi_y)
        (if f.water <> 0. then Printf.sprintf ", water_level %s" (num (f.water /. 65536.)) else "")
        (if f.smooth then ", smooth" else "")
        (if f.hierarchy then Printf.sprintf ", %d x %d blocks" f.nbx f.nbz else ", no hierarchy")
        (trans (Some t))
  | Superellipsoid { ex; ey; ez; tr } ->
      Printf.sprintf "superellipsoid { // powers %s, %s, %s%s" (num ex) (num ey) (num ez)
        (trans (if Transform.is_identity tr then None else Some tr))
  | Ovus { bottom; top; hpos; vpos; bvert; tvert; crad; sturm; tr } ->
      Printf.sprintf "ovus { %s, %s%s // joint: tube %s about a circle of %s at height %s, from %s to %s%s" (num bottom) (num top)
        (if sturm then " sturm" else "") (num crad) (num hpos) (num vpos) (num bvert) (num tvert)
        (trans (if Transform.is_identity tr then None else Some tr))
  | Sphere_sweep { interpolation; spheres; tolerance; trans = t } ->
      let kind = match interpolation with Linear -> "linear_spline" | Catmull_rom -> "cubic_spline" | B_spline -> "b_spline" in
      Printf.sprintf "sphere_sweep { %s %d, %s tolerance %s%s" kind (Array.length spheres)
        (String.concat ", " (Array.to_list (Array.map (fun (c, r) -> Printf.sprintf "%s, %s" (vec c) (num r)) spheres)))
        (num tolerance) (trans t)
  | Bicubic { patch_type; u_steps; v_steps; flatness; points; uv_vectors = st } ->
      let uvs =
        if st = [| 0.; 0.; 1.; 0.; 1.; 1.; 0.; 1. |] then ""
        else Printf.sprintf "uv_vectors %s " (String.concat ", " (List.map (fun i -> Printf.sprintf "<%s, %s>" (num st.(2 * i)) (num st.((2 * i) + 1))) [ 0; 1; 2; 3 ]))
      in
      Printf.sprintf "bicubic_patch { type %d flatness %s u_steps %d v_steps %d %s%s" patch_type (num flatness) u_steps v_steps uvs
        (String.concat ", " (Array.to_list (Array.map vec points)))
  | Isosurface i ->
      let container =
        match i.container with
        | Box_container { lo; hi } -> Printf.sprintf "box { %s, %s }" (vec lo) (vec hi)
        | Sphere_container { centre; radius } -> Printf.sprintf "sphere { %s, %s }" (vec centre) (num radius)
      in
      let evaluate = match i.evaluate with None -> "" | Some e -> Printf.sprintf " evaluate %s, %s, %s" (num e.p0) (num e.p1) (num e.p2) in
      Printf.sprintf "isosurface { function { … } // written at line %d\n  contained_by { %s } threshold %s accuracy %s max_gradient %s%s max_trace %d%s%s%s"
        i.fn.floc.Loc.line container (num i.threshold) (num i.accuracy) (num i.max_gradient) evaluate i.max_trace
        (if i.closed then "" else " open") (if i.copy then " // a copy" else "")
        (trans (if Transform.is_identity i.trans then None else Some i.trans))
  | Julia f ->
      let alg = match f.algebra with Quaternion -> "quaternion" | Hypercomplex -> "hypercomplex" in
      let fn =
        match f.func with
        | Sqr -> "sqr"
        | Cube -> "cube"
        | Reciprocal -> "reciprocal"
        | Func g -> (
            match g with
            | Exp -> "exp" | Ln -> "ln" | Sin -> "sin" | Asin -> "asin" | Cos -> "cos" | Acos -> "acos" | Tan -> "tan"
            | Atan -> "atan" | Sinh -> "sinh" | Asinh -> "asinh" | Cosh -> "cosh" | Acosh -> "acosh" | Tanh -> "tanh"
            | Atanh -> "atanh" | Pwr -> Printf.sprintf "pwr(%s, %s)" (num f.ex) (num f.ey))
      in
      Printf.sprintf "julia_fractal { <%s, %s, %s, %s> %s %s max_iteration %d precision %s slice <%s, %s, %s, %s>, %s%s // radius %s, exit %s%s"
        (num f.p0) (num f.p1) (num f.p2) (num f.p3) alg fn f.iterations (num (1. /. f.precision)) (num f.s0) (num f.s1) (num f.s2)
        (num f.s3) (num f.slice_dist) (if f.inverted then " inverted" else "") (num f.radius) (num f.exit_value) (trans f.trans)
  | Parametric m ->
      let fn (f : Fn.t) = if f.name = "" then "function { … }" else Printf.sprintf "function { %s(u, v) }" f.name in
      let container =
        match m.container with
        | Box_container b -> Printf.sprintf "box { <%s, %s, %s>, <%s, %s, %s> }" (num b.x0) (num b.y0) (num b.z0) (num b.x1) (num b.y1) (num b.z1)
        | Sphere_container { centre; radius } -> Printf.sprintf "sphere { %s, %s }" (vec centre) (num radius)
      in
      let pre =
        match m.precomputed with
        | None -> ""
        | Some p ->
            let axes = List.filteri (fun j _ -> Array.length p.low.(j) > 0) [ "x"; "y"; "z" ] in
            Printf.sprintf " precompute %d %s" p.levels (String.concat ", " axes)
      in
      Printf.sprintf "parametric { %s, %s, %s <%s, %s>, <%s, %s> contained_by { %s } accuracy %s max_gradient %s%s%s" (fn m.fx) (fn m.fy) (fn m.fz)
        (num m.umin) (num m.vmin) (num m.umax) (num m.vmax) container (num m.accuracy) (num m.max_gradient) pre
        (trans (if Transform.is_identity m.trans then None else Some m.trans))
  | Csg { kind; members } ->
      let member (m : member) =
        String.concat "\n  " (String.split_on_char '\n' (String.trim (obj m.mobj)))
        ^ (if m.inverted then " inverse" else "")
        ^ if m.own_interior then "" else " shared interior"
      in
      Printf.sprintf "%s {\n  %s"
        (match kind with Union -> "union" | Merge -> "merge" | Intersection -> "intersection" | Clipped -> "clipped (the first by the others)" | Bounded -> "bounded (the first by the others)" | Boxed -> "boxed (the first within the others' box)")
        (String.concat "\n  " (List.map member members))

and obj (o : obj) =
  Printf.sprintf "%s\n  %s%s%s%s\n} // %s\n" (shape o.shape) (texture o.texture)
    ((match o.interior_texture with None -> "" | Some t -> "\n  interior_" ^ texture t) ^ if o.uv_mapped then "\n  uv_mapping" else "")
    (interior o.interior)
    (String.concat ""
       (List.map
          (fun (on, flag) -> if on then "\n  " ^ flag else "")
          [ (o.no_shadow, "no_shadow"); (o.no_image, "no_image"); (o.no_reflection, "no_reflection"); (o.double_illuminate, "double_illuminate"); (o.looks_like, "// a light's looks_like") ]))
    (Loc.to_string o.loc)

(* radius and falloff of a spotlight are stored as cosines: written back as degrees *)
let light (l : light) =
  let deg c = num (acos c *. 180. /. Float.pi) in
  let kind =
    match l.kind with
    | Point_light -> ""
    | Spotlight -> Printf.sprintf " spotlight radius %s falloff %s tightness %s" (deg l.radius) (deg l.falloff) (num l.tightness)
    | Cylinder_light -> Printf.sprintf " cylinder radius %s falloff %s tightness %s" (num l.radius) (num l.falloff) (num l.tightness)
  in
  let aimed = l.parallel || match l.kind with Point_light -> false | Spotlight | Cylinder_light -> true in
  Printf.sprintf "light_source { %s, %s%s%s%s%s%s }\n" (vec l.position) (rgb l.colour) kind
    (match l.kind with Cylinder_light -> "" | Point_light | Spotlight -> if l.parallel then " parallel" else "")
    (if aimed then " point_at " ^ vec l.point_at else "")
    (if l.shadowless then " shadowless" else "")
    (if l.fade_distance <> 0. || l.fade_power <> 0. then
       Printf.sprintf " fade_distance %s fade_power %s" (num l.fade_distance) (num l.fade_power)
     else "")

let scene (s : t) =
  let b = Buffer.create 4096 in
  let add = Buffer.add_string b in
  add (Printf.sprintf "// version %s, %s\n" (num (float_of_int s.version /. 100.))
         (match s.gamma with Gamma_off -> "no gamma correction" | Working g -> "working gamma " ^ num g));
  add (Printf.sprintf "global_settings { max_trace_level %d adc_bailout %s ambient_light %s }\n" s.max_trace_level
         (num s.adc_bailout) (rgb s.ambient_light));
  let c = s.camera in
  add
    (Printf.sprintf "camera { %slocation %s direction %s up %s right %s }\n"
       (match c.projection with Perspective -> "" | Orthographic -> "orthographic ")
       (vec c.location) (vec c.direction) (vec c.up) (vec c.right));
  add (Printf.sprintf "background { %s }\n" (colour s.background));
  (match s.sky with
  | None -> ()
  | Some sk ->
      add
        (Printf.sprintf "sky_sphere { %s emission %s%s }\n"
           (String.concat " " (List.map (fun p -> Printf.sprintf "pigment { %s }" (pigment p)) sk.sky_pigments))
           (rgb sk.sky_emission)
           (match sk.sky_trans with None -> "" | Some t -> " " ^ matrix t)));
  List.iter (fun l -> add (light l)) s.lights;
  List.iter (fun o -> add (obj o)) s.objects;
  add (Printf.sprintf "// %d objects, %d lights\n" (List.length s.objects) (List.length s.lights));
  Buffer.contents b
