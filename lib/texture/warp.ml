(* Warps of pattern space (warps.cpp's Warp_EPoint), operation for operation as POV-Ray computes
   them, including the single-precision product of the repeat warp and the final clamp of every
   coordinate to ±1e17. *)

let two_pi = 2. *. Float.pi
let coordinate_limit = 1.0e17

(* C's (int) cast of a double on x86-64: truncation, and 0x80000000 outside the 32-bit range. *)
let c_int = C_float.c_int

(* Create_Warp's turbulence: no amount, 6 octaves, omega 0.5, lambda 2 *)
let default_turb = { Scene.turbulence = Vec.zero; octaves = 6; omega = 0.5; lambda = 2. }

let classic_turb (ws : Scene.warp list) =
  let rec last = function [] -> None | [ Scene.Classic_turb t ] -> Some t | _ :: rest -> last rest in
  last ws

(* ---------------------------------------------------------------------------------------------- *)
(* Turbulence, repeat and black holes *)

let turbulence (t : Scene.turb) (p : Vec.t) =
  let d = Noise.dturbulence t p in
  { Vec.x = p.x +. (d.x *. t.turbulence.x); y = p.y +. (d.y *. t.turbulence.y); z = p.z +. (d.z *. t.turbulence.z) }

let[@inline] coord (p : Vec.t) axis = match axis with 0 -> p.x | 1 -> p.y | _ -> p.z

(* The block number is stored in single precision and multiplied by the single-precision width in
   single precision; odd blocks are mirrored by [flip], a flipped axis shifted back by one width;
   then each block moves by its number times [offset]. *)
let repeat axis width (offset : Vec.t) (flip : Vec.t) (p : Vec.t) =
  let block = Precision.f32 (floor (coord p axis /. width)) in
  let along = coord p axis -. Precision.f32 (block *. width) in
  let x = if axis = 0 then along else p.x and y = if axis = 1 then along else p.y in
  let z = if axis = 2 then along else p.z in
  if c_int block land 1 = 0 then { Vec.x = x +. (block *. offset.x); y = y +. (block *. offset.y); z = z +. (block *. offset.z) }
  else begin
    let x = x *. flip.x and y = y *. flip.y and z = z *. flip.z in
    let back = coord flip axis < 0. in
    let x = if back && axis = 0 then width +. x else x and y = if back && axis = 1 then width +. y else y in
    let z = if back && axis = 2 then width +. z else z in
    { Vec.x = x +. (block *. offset.x); y = y +. (block *. offset.y); z = z +. (block *. offset.z) }
  end

(* The block of a repeated black hole along one axis: floor(p / r), or 0 when the axis does not
   repeat (r below 1e-10). *)
let[@inline] block p r = if r >= Precision.epsilon then c_int (floor (p /. r)) else 0

(* The centre of the black hole whose repeat block holds [p]: moved by the block's random
   uncertainty (WarpRands at the block's Hash3d) and by the block times the repeat vector. *)
let repeated_centre (centre : Vec.t) (r : Vec.t) uncertainty (p : Vec.t) =
  let bx = block p.x r.x and by = block p.y r.y and bz = block p.z r.z in
  match uncertainty with
  | None -> { Vec.x = centre.x +. (r.x *. float bx); y = centre.y +. (r.y *. float by); z = centre.z +. (r.z *. float bz) }
  | Some (u : Vec.t) ->
      let seed = Noise.hash3d bx by bz in
      {
        Vec.x = centre.x +. (Noise.random_double seed *. u.x) +. (r.x *. float bx);
        y = centre.y +. (Noise.random_double (seed + 1) *. u.y) +. (r.y *. float by);
        z = centre.z +. (Noise.random_double (seed + 2) *. u.z) +. (r.z *. float bz);
      }

(* Inside the radius, a type-0 black hole moves the sampled point away from its centre by
   s·(p − centre), s = ((radius − distance) / radius)^falloff · strength, at most 1, so that the
   pattern looks drawn into the hole; inverted, it moves the point toward the centre. Other types
   leave the point alone. The fields arrive one by one because an inline record cannot be passed
   on whole. *)
let black_hole centre radius strength power inverted bh_type repeat uncertainty (p : Vec.t) =
  let c = match repeat with None -> centre | Some r -> repeated_centre centre r uncertainty p in
  let dx = p.x -. c.x and dy = p.y -. c.y and dz = p.z -. c.z in
  let length = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  if length >= radius || bh_type <> 0 then p
  else begin
    let share = (radius -. length) /. radius in
    let s = Float.pow share power *. strength in
    let s = if s > 1.0 then 1.0 else s in
    let s = if inverted then -.s else s in
    { Vec.x = p.x +. (dx *. s); y = p.y +. (dy *. s); z = p.z +. (dz *. s) }
  end

(* ---------------------------------------------------------------------------------------------- *)
(* The mapping warps: cylindrical, spherical, toroidal, planar (warps.cpp, after the image maps)
   and cubic (JN2007). Each maps the point to <u, v, distance>, then turns that triple by the
   orientation unless it is exactly <0,0,1>. *)

let orient (o : Vec.t) x y z =
  if o.x = 0.0 && o.y = 0.0 && o.z = 1.0 then { Vec.x; y; z }
  else
    {
      Vec.x = (o.x *. z) +. (o.y *. x) +. (o.z *. x);
      y = (o.x *. y) +. (o.y *. -.z) +. (o.z *. y);
      z = (o.x *. -.x) +. (o.y *. y) +. (o.z *. z);
    }

(* The angle of (x, z) from the x axis, counter-clockwise toward +z, in [0, 2π); [len] is
   √(x² + z²), not 0. *)
let[@inline] angle x z len =
  if z = 0.0 then if x > 0. then 0.0 else Float.pi
  else
    let theta = acos (x /. len) in
    if z < 0.0 then two_pi -. theta else theta

let[@inline] scaled_by_distance dist_exp len v =
  if dist_exp = 1.0 then v *. len else if dist_exp <> 0.0 then v *. Float.pow len dist_exp else v

let cylindrical orientation dist_exp (p : Vec.t) =
  let len = sqrt ((p.x *. p.x) +. (p.z *. p.z)) in
  if len = 0.0 then p
  else
    let theta = angle p.x p.z len /. two_pi in
    orient orientation (scaled_by_distance dist_exp len theta) p.y len

let spherical orientation dist_exp (p : Vec.t) =
  let dist = sqrt ((p.x *. p.x) +. (p.y *. p.y) +. (p.z *. p.z)) in
  if dist = 0.0 then p
  else begin
    let x = p.x /. dist and y = p.y /. dist and z = p.z /. dist in
    let phi = 0.5 +. (asin y /. Float.pi) in
    let len = sqrt ((x *. x) +. (z *. z)) in
    let theta = if len = 0.0 then 0. else angle x z len /. two_pi in
    orient orientation (scaled_by_distance dist_exp dist theta) (scaled_by_distance dist_exp dist phi) dist
  end

let toroidal orientation dist_exp major_radius (p : Vec.t) =
  let len = sqrt ((p.x *. p.x) +. (p.z *. p.z)) in
  if len = 0.0 then p
  else begin
    let theta = 0.0 -. angle p.x p.z len in
    let x = len -. major_radius in
    let len = sqrt ((x *. x) +. (p.y *. p.y)) in
    let phi = acos (-.x /. len) in
    let phi = if p.y > 0.0 then two_pi -. phi else phi in
    let theta = theta /. -.two_pi and phi = phi /. two_pi in
    orient orientation (scaled_by_distance dist_exp len theta) (scaled_by_distance dist_exp len phi) len
  end

let planar orientation offset (p : Vec.t) = orient orientation p.x p.y offset

(* The six faces of the cube unfold into a cross in [0,1]²: −x, +z, +x, −z side by side in the
   middle third, +y above and −y below the +z face; z becomes the distance along the face's axis. *)
let cubic (p : Vec.t) =
  let x = p.x and y = p.y and z = p.z in
  let ax = Float.abs x and ay = Float.abs y and az = Float.abs z in
  let third = 1.0 /. 3.0 in
  if x >= 0. && x >= ay && x >= az then
    { Vec.x = 0.75 -. (0.25 *. ((z /. x) +. 1.0) /. 2.0); y = third +. (third *. ((y /. x) +. 1.0) /. 2.0); z = x }
  else if y >= 0. && y >= ax && y >= az then
    { Vec.x = 0.25 +. (0.25 *. ((x /. y) +. 1.0) /. 2.0); y = 1.0 -. (third *. ((z /. y) +. 1.0) /. 2.0); z = y }
  else if z >= 0. && z >= ax && z >= ay then
    { Vec.x = 0.25 +. (0.25 *. ((x /. z) +. 1.0) /. 2.0); y = third +. (third *. ((y /. z) +. 1.0) /. 2.0); z }
  else if x < 0. && x <= -.ay && x <= -.az then
    let x = -.x in
    { Vec.x = 0.25 *. ((z /. x) +. 1.0) /. 2.0; y = third +. (third *. ((y /. x) +. 1.0) /. 2.0); z = x }
  else if y < 0. && y <= -.ax && y <= -.az then
    let y = -.y in
    { Vec.x = 0.25 +. (0.25 *. ((x /. y) +. 1.0) /. 2.0); y = third *. ((z /. y) +. 1.0) /. 2.0; z = y }
  else
    let z = -.z in
    { Vec.x = 1.0 -. (0.25 *. ((x /. z) +. 1.0) /. 2.0); y = third +. (third *. ((y /. z) +. 1.0) /. 2.0); z }

(* ---------------------------------------------------------------------------------------------- *)

let[@inline] within_limit v = not (v > coordinate_limit || v < -.coordinate_limit)

let[@inline] clamp_coordinate v =
  if v > coordinate_limit then coordinate_limit else if v < -.coordinate_limit then -.coordinate_limit else v

let rec through (pat : Scene.pattern) (p : Vec.t) (ws : Scene.warp list) =
  match ws with
  | [] ->
      if within_limit p.x && within_limit p.y && within_limit p.z then p
      else { Vec.x = clamp_coordinate p.x; y = clamp_coordinate p.y; z = clamp_coordinate p.z }
  | w :: rest ->
      let p =
        match w with
        | Scene.Transform_warp t -> Transform.inv_point t p
        | Classic_turb t -> ( match pat with Marble | Wood -> p | _ -> turbulence t p)
        | Turb_warp t -> turbulence t p
        | Repeat_warp { axis; width; offset; flip } -> repeat axis width offset flip p
        | Black_hole { centre; radius; strength; power; inverted; bh_type; repeat; uncertainty } ->
            black_hole centre radius strength power inverted bh_type repeat uncertainty p
        | Cylindrical_warp { orientation; dist_exp } -> cylindrical orientation dist_exp p
        | Spherical_warp { orientation; dist_exp } -> spherical orientation dist_exp p
        | Toroidal_warp { orientation; dist_exp; major_radius } -> toroidal orientation dist_exp major_radius p
        | Planar_warp { orientation; offset } -> planar orientation offset p
        | Cubic_warp -> cubic p
      in
      through pat p rest

let point (ws : Scene.warp list) (pat : Scene.pattern) (p : Vec.t) = through pat p ws
