(* Light sources and the samples of light they give a point (§3.3, §3.4, §18). *)

let f32 = Precision.f32
let epsilon = Precision.epsilon

type spread =
  | Everywhere
  | Spot of { radius_cos : float; falloff_cos : float; tightness : float }
  | Beam of { beam_radius : float; beam_falloff : float; beam_tightness : float }

type t = {
  lx : float;
  ly : float;
  lz : float;
  lcolour : Rgb.t;
  shadowless : bool;
  fade : bool;
  lfade_distance : float;
  lfade_power : float;
  spread : spread;
  parallel : bool;
  dx : float;
  dy : float;
  dz : float;
}

let compile (l : Scene.light) =
  (* §14.8: normalize(point_at − centre), left as it is when shorter than EPSILON *)
  let dir =
    let v = Vec.sub l.point_at l.position in
    let len = Vec.length v in
    if len > epsilon then Vec.make (v.x /. len) (v.y /. len) (v.z /. len) else v
  in
  {
    lx = l.position.x;
    ly = l.position.y;
    lz = l.position.z;
    lcolour = Rgb.make (f32 l.colour.r) (f32 l.colour.g) (f32 l.colour.b);
    shadowless = l.shadowless;
    fade = l.fade_power > 0. && Float.abs l.fade_distance > epsilon;
    lfade_distance = l.fade_distance;
    lfade_power = l.fade_power;
    spread =
      (match l.kind with
      | Point_light -> Everywhere
      | Spotlight -> Spot { radius_cos = l.radius; falloff_cos = l.falloff; tightness = l.tightness }
      | Cylinder_light -> Beam { beam_radius = l.radius; beam_falloff = l.falloff; beam_tightness = l.tightness });
    parallel = l.parallel;
    dx = dir.x;
    dy = dir.y;
    dz = dir.z;
  }

let cubic_spline lo hi p = if p < lo then 0. else if p >= hi then 1. else let s = (p -. lo) /. (hi -. lo) in (3. -. (2. *. s)) *. s *. s

(* the attenuation of a light ray along (lx, ly, lz), inlined where a sample is written so that
   its value is not boxed *)
let[@inline] attenuation_along (lt : t) (p : Vec.t) lx ly lz dist =
  let a =
    match lt.spread with
    | Everywhere -> 1.
    | Spot c ->
        (* the ray's cosine with the spot axis, turned round for a light in front of the point *)
        let ct = (lx *. lt.dx) +. (ly *. lt.dy) +. (lz *. lt.dz) in
        let ct = if dist > 0. then -.ct else ct in
        if ct > 0. then
          let a = Float.pow ct c.tightness in
          if c.radius_cos > 0. && ct < c.radius_cos then a *. cubic_spline c.falloff_cos c.radius_cos ct else a
        else 0.
    | Beam b ->
        (* §18.2: the point's distance from the beam's axis, on the lit side of the centre *)
        let vx = p.x -. lt.lx and vy = p.y -. lt.ly and vz = p.z -. lt.lz in
        let k = (vx *. lt.dx) +. (vy *. lt.dy) +. (vz *. lt.dz) in
        if k > 0. then
          let qx = vx -. (k *. lt.dx) and qy = vy -. (k *. lt.dy) and qz = vz -. (k *. lt.dz) in
          let len = sqrt ((qx *. qx) +. (qy *. qy) +. (qz *. qz)) in
          if len < b.beam_falloff then
            let r = 1. -. (len /. b.beam_falloff) in
            let a = Float.pow r b.beam_tightness in
            if b.beam_radius > 0. && len > b.beam_radius then a *. cubic_spline 0. (1. -. (b.beam_radius /. b.beam_falloff)) r else a
          else 0.
        else 0.
  in
  if a > 0. && lt.fade then a *. (2. /. (1. +. Float.pow (dist /. lt.lfade_distance) lt.lfade_power)) else a

let attenuation lt p (l : Vec.t) dist = attenuation_along lt p l.x l.y l.z dist

(* ComputeOneWhiteLightRay: dist·(−dir·l), the signed distance of the point in front of the plane
   through the centre perpendicular to dir. *)
let[@inline] parallel_depth_along (lt : t) lx ly lz dist = dist *. -.((lt.dx *. lx) +. (lt.dy *. ly) +. (lt.dz *. lz))
let parallel_depth lt (l : Vec.t) dist = parallel_depth_along lt l.x l.y l.z dist

type sample = { mutable dx : float; mutable dy : float; mutable dz : float; mutable dist : float; mutable atten : float }

let room () = { dx = 0.; dy = 0.; dz = 0.; dist = 0.; atten = 1. }
let samples (_ : t) = 1

let sample lt (p : Vec.t) (_ : int) (s : sample) =
  let lvx = lt.lx -. p.x and lvy = lt.ly -. p.y and lvz = lt.lz -. p.z in
  let dist = sqrt ((lvx *. lvx) +. (lvy *. lvy) +. (lvz *. lvz)) in
  (* ComputeOneWhiteLightRay: VInverseScaleEq, times the reciprocal of the distance; the last bit
     decides knife-edge shadow rays, such as one through faces shared by CSG members *)
  let k = 1. /. dist in
  let lx = lvx *. k and ly = lvy *. k and lz = lvz *. k in
  if lt.parallel then begin
    (* §18.3: a parallel light's ray runs along −dir, as far as the plane through the centre *)
    s.dist <- parallel_depth_along lt lx ly lz dist;
    s.dx <- -.lt.dx;
    s.dy <- -.lt.dy;
    s.dz <- -.lt.dz
  end
  else begin
    s.dist <- dist;
    s.dx <- lx;
    s.dy <- ly;
    s.dz <- lz
  end;
  s.atten <- attenuation_along lt p s.dx s.dy s.dz s.dist

let[@inline] colour lt (s : sample) =
  let a = s.atten in
  if a <> 1. then Rgb.make (f32 (lt.lcolour.r *. a)) (f32 (lt.lcolour.g *. a)) (f32 (lt.lcolour.b *. a)) else lt.lcolour

let[@inline] direction (s : sample) = Vec.make s.dx s.dy s.dz
