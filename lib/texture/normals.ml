(* Perturbed normals, after POV-Ray 3.7's normal.cpp (Perturb_Normal and the functions it calls).

   A normal pattern changes the direction of the surface normal at a point and nothing else. Three
   ways lead to the new normal, chosen by the normal's pattern and map:
   - a normal_map (on any pattern but average): the pattern's value picks two entries, each entry's
     normal perturbs the normal, and the two results are blended by the value;
   - a pattern with a normal of its own (bumps, dents, ripples, waves, wrinkles, quilted, facets,
     average): a vector is added to the normal (facets replaces it);
   - any other pattern: the slope of its value, sampled at the four corners of a small tetrahedron
     around the point (through the slope_map when there is one), is added to the normal.
   In each, the normal is first taken into the pattern's space (the inverse of its transforms) and
   brought back after, normalised on both ways unless no_bump_scale. The values POV-Ray stores in
   single precision (the bump size, the accuracy, frequency and phase, map values) are rounded the
   same way before use. *)

let f32 = Precision.f32

(* Pyramid_Vect: the unit vectors from the centre of a regular tetrahedron to its corners, the
   last one straight up *)
let pyramid =
  [|
    Vec.make 0.942809041 (-0.333333333) 0.0;
    Vec.make (-0.471404521) (-0.333333333) 0.816496581;
    Vec.make (-0.471404521) (-0.333333333) (-0.816496581);
    Vec.make 0.0 1.0 0.0;
  |]

(* MInvTransNormal: the normal times the transposed matrix, which takes a normal from world space
   into the pattern's space (whose points are mapped by the inverse) *)
let inv_trans_normal (t : Transform.t) (n : Vec.t) =
  {
    Vec.x = (n.x *. t.m00) +. (n.y *. t.m01) +. (n.z *. t.m02);
    y = (n.x *. t.m10) +. (n.y *. t.m11) +. (n.z *. t.m12);
    z = (n.x *. t.m20) +. (n.y *. t.m21) +. (n.z *. t.m22);
  }

(* Only the transforms among a pattern's warps turn its normal; the other warps move points only *)
let transform_of (w : Scene.warp) =
  match w with
  | Transform_warp t -> Some t
  | Classic_turb _ | Turb_warp _ | Repeat_warp _ | Black_hole _ | Cylindrical_warp _ | Spherical_warp _ | Toroidal_warp _
  | Planar_warp _ | Cubic_warp ->
      None

(* Warp_Normal: from world space into the pattern's space, the warps walked from the head (the last
   written first), as the point is *)
let warp_normal (ws : Scene.warp list) ~keep_scale n =
  let n = if keep_scale then n else Transform.normalize n in
  let n = List.fold_left (fun n w -> match transform_of w with Some t -> inv_trans_normal t n | None -> n) n ws in
  if keep_scale then n else Transform.normalize n

(* UnWarp_Normal: back to world space, the warps walked from the last element to the head *)
let unwarp_normal (ws : Scene.warp list) ~keep_scale n =
  let n = if keep_scale then n else Transform.normalize n in
  let n = List.fold_right (fun w n -> match transform_of w with Some t -> Transform.normal t n | None -> n) ws n in
  if keep_scale then n else Transform.normalize n

let two_pi = 6.283185307179586476925286766560

(* cycloidal: sin(2π·v) through the fraction of v scaled by 50000 and back, odd about zero *)
let cycloidal v =
  if v >= 0. then sin ((v -. floor v) *. 50000. /. 50000. *. two_pi)
  else 0. -. sin ((0. -. (v +. floor (0. -. v))) *. 50000. /. 50000. *. two_pi)

(* FLOOR of texture.h: floor for x ≥ 0, and −floor(−x) − 1 below (one less than floor for negative
   integers) *)
let pov_floor x = if x >= 0. then floor x else 0. -. floor (0. -. x) -. 1.

(* ripples: each source adds the vector from it to the point, scaled by the sine of its distance *)
let ripples number_of_waves (nm : Scene.normal) amount (q : Vec.t) (n : Vec.t) =
  let wave_sources = Noise.wave_sources number_of_waves in
  let count = float_of_int number_of_waves in
  let n = ref n in
  for i = 0 to number_of_waves - 1 do
    let pt = Vec.sub q wave_sources.(i) in
    let len = sqrt ((pt.x *. pt.x) +. (pt.y *. pt.y) +. (pt.z *. pt.z)) in
    let len = if len = 0. then 1. else len in
    let index = (len *. f32 nm.nfrequency) +. f32 nm.nphase in
    let scalar = cycloidal index *. amount in
    n := Vec.madd !n (scalar /. (len *. count)) pt
  done;
  !n

(* waves: as ripples, each source with its own frequency, its amplitude divided by it *)
let waves_normal number_of_waves (nm : Scene.normal) amount (q : Vec.t) (n : Vec.t) =
  let wave_sources = Noise.wave_sources number_of_waves and wave_frequencies = Noise.wave_frequencies number_of_waves in
  let count = float_of_int number_of_waves in
  let n = ref n in
  for i = 0 to number_of_waves - 1 do
    let pt = Vec.sub q wave_sources.(i) in
    let len = sqrt ((pt.x *. pt.x) +. (pt.y *. pt.y) +. (pt.z *. pt.z)) in
    let len = if len = 0. then 1. else len in
    let fr = wave_frequencies.(i) in
    let index = (len *. f32 nm.nfrequency *. fr) +. f32 nm.nphase in
    let scalar = cycloidal index *. amount /. fr in
    n := Vec.madd !n (scalar /. (len *. count)) pt
  done;
  !n

(* wrinkles: ten octaves of the vector noise, each component's magnitude summed *)
let wrinkles amount (q : Vec.t) (n : Vec.t) =
  let rx = ref 0. and ry = ref 0. and rz = ref 0. and scale = ref 1. in
  for _ = 0 to 9 do
    let s = !scale in
    let v = Noise.dnoise (Vec.make (q.x *. s) (q.y *. s) (q.z *. s)) in
    rx := !rx +. Float.abs (v.x /. s);
    ry := !ry +. Float.abs (v.y /. s);
    rz := !rz +. Float.abs (v.z /. s);
    scale := s *. 2.
  done;
  Vec.madd n amount (Vec.make !rx !ry !rz)

(* quilt_cubic: the Bézier curve with ends 0 and 1 and control values c0, c1, over √(3/4) *)
let quilt_cubic t c0 c1 =
  let it = 1. -. t in
  let itsqrd = it *. it in
  let tsqrd = t *. t in
  let tcubed = t *. tsqrd in
  (tcubed +. (3.0 *. t *. itsqrd *. c0) +. (3.0 *. tsqrd *. it *. c1)) *. 1.154700538

(* quilted: the offset from the centre of the unit cell, scaled by the cubic of its length *)
let quilted amount c0 c1 (q : Vec.t) (n : Vec.t) =
  let vx = q.x -. pov_floor q.x -. 0.5 and vy = q.y -. pov_floor q.y -. 0.5 and vz = q.z -. pov_floor q.z -. 0.5 in
  let t = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  let t = quilt_cubic t (f32 c0) (f32 c1) in
  Vec.madd n amount (Vec.make (vx *. t) (vy *. t) (vz *. t))

(* PickInCube: the random point of the unit cube holding [tv] (floor taken just below each
   coordinate), from the cube's hash *)
let pick_in_cube (tv : Vec.t) =
  let fx = floor (tv.x -. Precision.epsilon) and fy = floor (tv.y -. Precision.epsilon) and fz = floor (tv.z -. Precision.epsilon) in
  let seed = Noise.hash3d (int_of_float fx) (int_of_float fy) (int_of_float fz) in
  Vec.make (fx +. Noise.random_double seed) (fy +. Noise.random_double (seed + 1)) (fz +. Noise.random_double (seed + 2))

(* The 81 offsets facets searches: every cube within two steps along at most one axis and one
   step along the others, in POV-Ray's loop order (x outermost) *)
let facet_offsets =
  let l = ref [] in
  for ix = 0 to 4 do
    for iy = 0 to 4 do
      for iz = 0 to 4 do
        let ax = float_of_int (ix - 2) and ay = float_of_int (iy - 2) and az = float_of_int (iz - 2) in
        let far a = if Float.abs a > 1.5 then 1 else 0 in
        if far ax + far ay + far az <= 1 then l := Vec.make ax ay az :: !l
      done
    done
  done;
  Array.of_list (List.rev !l)

(* POV-Ray's facets keeps, per render thread, the random points of the 81 cubes around the last
   cube it searched, and the hash ("seed") of that cube: a later point whose cube has the same
   hash reuses them, even when it is another cube (4096 hashes for all cubes). *)
type facets_cache = { mutable last_seed : int; points : Vec.t array }

(* Facets_Last_Seed starts at 0x80000000, which no hash (0…4095) equals *)
let no_seed = -0x80000000
let facets_cache () = { last_seed = no_seed; points = Array.make (Array.length facet_offsets) Vec.zero }
let reset_facets c = c.last_seed <- no_seed

(* The hash of the cube holding [tv], as PickInCube returns it *)
let cube_seed (tv : Vec.t) =
  let fx = floor (tv.x -. Precision.epsilon) and fy = floor (tv.y -. Precision.epsilon) and fz = floor (tv.z -. Precision.epsilon) in
  Noise.hash3d (int_of_float fx) (int_of_float fy) (int_of_float fz)

(* facets: the nearest random cube point to the scaled normal (or, with coords, to the scaled point)
   under the metric; without coords it becomes the normal, with coords the vector noise there,
   less its component along the normal, is added to it. The candidates are the cached ones when
   the cube's hash is the cache's, else the 81 around [tv] (stored in the cache when there is one). *)
let facets cache ~size ~coords ~metric (q : Vec.t) (n : Vec.t) =
  let n = Transform.normalize n in
  let tv = if coords <> 0. then q else n in
  let scale = if size < 1e-6 then 1e6 else 1. /. size in
  let tv = Vec.make (tv.x *. scale) (tv.y *. scale) (tv.z *. scale) in
  let points =
    match cache with
    | Some c ->
        let seed = cube_seed tv in
        if seed <> c.last_seed then begin
          Array.iteri (fun i o -> c.points.(i) <- pick_in_cube (Vec.add tv o)) facet_offsets;
          c.last_seed <- seed
        end;
        c.points
    | None -> Array.map (fun o -> pick_in_cube (Vec.add tv o)) facet_offsets
  in
  let distance (c : Vec.t) =
    let dx = c.x -. tv.x and dy = c.y -. tv.y and dz = c.z -. tv.z in
    if metric = 2. then (dx *. dx) +. (dy *. dy) +. (dz *. dz)
    else if metric = 1. then dx +. dy +. dz
    else Float.pow (Float.abs dx) metric +. Float.pow (Float.abs dy) metric +. Float.pow (Float.abs dz) metric
  in
  let best = ref points.(0) in
  let best_d = ref (distance !best) in
  for i = 1 to Array.length points - 1 do
    let d = distance points.(i) in
    if d < !best_d then begin
      best_d := d;
      best := points.(i)
    end
  done;
  if coords <> 0. then
    let pert = Noise.dnoise !best in
    let along = Vec.dot pert n in
    let pert = Vec.sub pert (Vec.make (n.x *. along) (n.y *. along) (n.z *. along)) in
    (* the coords value scales the perturbation *)
    Vec.madd n coords pert
  else !best

(* Search_Blend_Map over [count] entries whose values [value_of] gives: the entries before and at
   [v] ([prev] = [cur] beyond the ends and on an entry's value) *)
let search count value_of v =
  let last = count - 1 in
  if v >= value_of last then (last, last)
  else
    let rec go prev i = if v > value_of i then go i (i + 1) else (prev, i) in
    let prev, cur = go 0 0 in
    if v = value_of cur then (cur, cur) else (prev, cur)

(* Hermite_Cubic: the cubic through (0, h1) and (1, h2) with slopes s1 and s2 *)
let hermite_cubic t (e1 : Scene.slope_entry) (e2 : Scene.slope_entry) =
  let tt = t *. t in
  let ttt = tt *. t in
  let rv = ttt *. (e1.slope +. e2.slope +. (2.0 *. (e1.height -. e2.height))) in
  let rv = rv +. (-.tt *. ((2.0 *. e1.slope) +. e2.slope +. (3.0 *. (e1.height -. e2.height)))) in
  rv +. ((t *. e1.slope) +. e1.height)

let slope_value (map : Scene.slope_entry array) v =
  let value_of i = f32 map.(i).svalue in
  let prev, cur = search (Array.length map) value_of v in
  if prev = cur then map.(cur).height
  else hermite_cubic ((v -. value_of prev) /. (value_of cur -. value_of prev)) map.(prev) map.(cur)

(* Do_Slope_Map: the value itself without a slope_map *)
let mapped_value (m : Scene.normal_map) v =
  match m with No_map | Normal_map _ -> v | Slope_map map -> slope_value map v

(* Evaluate_TPat: the raw pattern value at the pattern-space point (waves and ripples use the
   frequency and phase inside it too), wrapped and shaped *)
let pattern_value gen (nm : Scene.normal) hit q =
  let g = if nm.nnoise_generator = 0 then gen else nm.nnoise_generator in
  let frequency = f32 nm.nfrequency and phase = f32 nm.nphase in
  Pigment.shape_value ~frequency ~phase nm.nwave (Patterns.value_with ~frequency ~phase nm.npattern nm.nwarps g hit q)

let warp_point (nm : Scene.normal) p = Warp.point nm.nwarps nm.npattern p

(* Perturb_Normal. [hit.normal] is what POV-Ray's intersection holds as its perturbed normal when
   the call starts (the slope and aoi patterns read it): every call leaves its result there, so a
   map's second entry and an average's later entries see the one before. [keep_scale] is
   no_bump_scale, passed down from a normal to the normals of its map (Post_Tnormal). *)
let rec perturb_in cache gen ~keep_scale (nm : Scene.normal) (p : Vec.t) (hit : Patterns.hit) (n : Vec.t) : Vec.t =
  (* UV_MAP_PATTERN: the normal inside the wrapper perturbs at the hit's (u, v, 0), and the result
     is normalised *)
  if nm.nuv_mapping then Vec.normalize (perturb_at cache gen ~keep_scale nm hit.uv hit n) else perturb_at cache gen ~keep_scale nm p hit n

and perturb_at cache gen ~keep_scale (nm : Scene.normal) (p : Vec.t) (hit : Patterns.hit) (n : Vec.t) : Vec.t =
  let keep_scale = keep_scale || nm.no_bump_scale in
  match (nm.nmap, nm.npattern) with
  | Normal_map entries, pat when (match pat with Average -> false | _ -> true) ->
      let q = warp_point nm p in
      let v = pattern_value gen nm hit q in
      let value_of i = f32 entries.(i).nvalue in
      let prev, cur = search (Array.length entries) value_of v in
      let n = warp_normal nm.nwarps ~keep_scale n in
      let nc = perturb_in cache gen ~keep_scale entries.(cur).nnormal q hit n in
      let n =
        if prev = cur then nc
        else
          let np = perturb_in cache gen ~keep_scale entries.(prev).nnormal q { hit with normal = nc } n in
          let w2 = (v -. value_of prev) /. (value_of cur -. value_of prev) in
          let w1 = 1.0 -. w2 in
          Vec.make ((w1 *. np.x) +. (w2 *. nc.x)) ((w1 *. np.y) +. (w2 *. nc.y)) ((w1 *. np.z) +. (w2 *. nc.z))
      in
      Transform.normalize (unwarp_normal nm.nwarps ~keep_scale n)
  | (No_map | Slope_map _ | Normal_map _), pat -> (
      let own f =
        let n = warp_normal nm.nwarps ~keep_scale n in
        let q = warp_point nm p in
        unwarp_normal nm.nwarps ~keep_scale (f q n)
      in
      let amount = f32 nm.amount in
      match pat with
      | Bumps -> own (fun q n -> Vec.madd n amount (Noise.dnoise q))
      | Dents ->
          own (fun q n ->
              let g = if nm.nnoise_generator = 0 then gen else nm.nnoise_generator in
              let v = Noise.noise g q in
              Vec.madd n (v *. v *. v *. amount) (Noise.dnoise q))
      | Ripples k -> own (ripples k nm amount)
      | Waves k -> own (waves_normal k nm amount)
      | Wrinkles -> own (wrinkles amount)
      | Quilted { control0; control1 } -> own (quilted amount control0 control1)
      | Facets { fsize; coords; fmetric } -> own (facets cache ~size:fsize ~coords ~metric:fmetric)
      | Average -> own (average cache gen ~keep_scale nm hit)
      | Bitmap b -> own (Image_map.bump b amount)
      | Checker | Gradient _ | Hexagon | Brick _ | Square | Triangular | Cubic | Agate _ | Bozo | Spotted | Granite | Leopard
      | Marble | Wood | Onion | Radial | Cells | Crackle _ | Spiral1 _ | Spiral2 _ | Planar | Boxed | Spherical | Cylindrical
      | Fractal _ | Pavement _ | Tiling _ | Aoi | Slope _ | Object_pattern _ | Pigment_pattern _ | No_pattern | Image_pattern _
      | Function_pattern _ ->
          (* the slope of the value: four samples at the corners of a tetrahedron of size
             [accuracy] around the point, each pushing the normal along its corner's direction *)
          let n = warp_normal nm.nwarps ~keep_scale n in
          let delta = f32 nm.accuracy in
          let amount = amount *. -5.0 in
          let amount = amount *. (0.02 /. delta) in
          let q = warp_point nm p in
          let n = ref n in
          for i = 0 to 3 do
            let c = pyramid.(i) in
            let s = Vec.madd q delta c in
            let v = mapped_value nm.nmap (pattern_value gen nm hit s) in
            n := Vec.madd !n (v *. amount) c
          done;
          unwarp_normal nm.nwarps ~keep_scale !n)

(* Do_Average_Normals: each entry of the map perturbs the (pattern-space) normal, and the results
   are averaged with the entries' values as weights, summed in single precision *)
and average cache gen ~keep_scale (nm : Scene.normal) hit (q : Vec.t) (n : Vec.t) =
  let entries = match nm.nmap with Normal_map e -> e | No_map | Slope_map _ -> [||] in
  let sum = ref Vec.zero and total = ref 0. and pnormal = ref hit.Patterns.normal in
  Array.iter
    (fun (e : Scene.normal_entry) ->
      let w = f32 e.nvalue in
      let v = perturb_in cache gen ~keep_scale e.nnormal q { hit with normal = !pnormal } n in
      pnormal := v;
      sum := Vec.madd !sum w v;
      total := f32 (!total +. w))
    entries;
  let k = 1.0 /. !total in
  Vec.make (!sum.x *. k) (!sum.y *. k) (!sum.z *. k)

let perturb ?facets gen nm p hit n = perturb_in facets gen ~keep_scale:false nm p hit n

(* trace.cpp: after a no_bump_scale normal, Vector3d::normalize (a division by the length) *)
let layer_normal (nm : Scene.normal) (v : Vec.t) =
  (* the flag trace.cpp tests is the uv_mapping wrapper's own, which is never set *)
  if nm.no_bump_scale && not nm.nuv_mapping then
    let l = sqrt ((v.x *. v.x) +. (v.y *. v.y) +. (v.z *. v.z)) in
    if l <> 0. then Vec.make (v.x /. l) (v.y /. l) (v.z /. l) else v
  else v
