(* The recursive Whitted tracer, following POVRAY-3.7 §2–§7 and Appendix B. A traced colour is a
   function of the compiled scene and the ray; the only mutation is the per-worker statistics and a
   one-slot scratch for the nearest depth, both invisible to callers. *)

open Compiled

let epsilon = 1e-10
(* §2.1: shapes reject roots at or below 1e-6 and beyond 1e7: Limits.pov *)
let min_isect_depth = 1e-4 (* §2.1: every ray ignores hits closer than 1e-4 *)
let shadow_tolerance = 1e-3 (* §4: shadow hits count only from 1e-3 to the light minus 1e-3 *)

type result = { r : float; g : float; b : float; tr : float }

(* Colours are single precision in POV-Ray (§8.3): colour arithmetic is rounded the same way. *)
let[@inline] f32 x = Int32.float_of_bits (Int32.bits_of_float x)

type ctx = {
  scene : Compiled.t;
  stats : Stats.t;
  depth : float array;  (* scratch: depth of the last hit *)
  sub : int array;  (* scratch: the mesh face of the last hit *)
  stack : float array;  (* traversal room for the scene's hierarchy … *)
  mstack : float array;  (* … and for a mesh's *)
  lim : Limits.t;  (* the depths shapes accept *)
  min_depth : float;  (* the nearest depth any ray accepts *)
  robust : bool;  (* secondary rays leave from points lifted off the surface *)
  shadow_cache : int array;  (* §4: per light, the opaque object that last blocked it, or −1 *)
  slab : float array;  (* scratch: a box's crossings and sides (tmin, tmax, smin, smax) *)
  hits : hits;  (* scratch: the hits of a CSG's members (§16.2) *)
  leaf : int array;  (* scratch: the member hit in a CSG *)
  qhits : float array;  (* scratch: every hit of one cylinder, cone or disc, as (depth, part) pairs *)
  torus : Torus.work;  (* room for a torus's quartic and its roots *)
  ghits : hits;  (* scratch: every crossing of one text letter, as (depth, part) pairs *)
  near : float array;
      (* scratch of [nearest]: the best depth so far, the ray's reciprocal direction, the least
         depth accepted *)
  walk_lim : float array;  (* scratch of [nearest]: the limit of the hierarchy's walk *)
  best : best;  (* scratch of [nearest]: the best object so far and its mesh face *)
}

and best = { mutable best_id : int; mutable best_face : int }

(* Room for the hits of a CSG's members: [hit_width] floats per hit (depth, sub, leaf id, and the
   hit point x, y, z), grown when a ray crosses more surfaces than it holds. *)
and hits = { mutable h : float array }

let hit_width = 6

(* POV-Ray keeps two cache slots per light: one for the shadow tests made while shading a hit at
   trace level 2 (lightSourceLevel1ShadowCache) and one for every other level. *)
(* A cylinder or cone has at most 4 crossings listed (two on the side, the two ends), a disc one. *)
let max_hits = 8

let make_ctx ?(robust = false) scene stats =
  let slots = 2 * max 1 (Array.length scene.lights) in
  {
    scene;
    stats;
    depth = [| 0. |];
    sub = [| -1 |];
    stack = Array.make 512 0.;
    mstack = Array.make 512 0.;
    lim = (if robust then Limits.robust else Limits.pov);
    min_depth = (if robust then 0. else min_isect_depth);
    robust;
    shadow_cache = Array.make slots (-1);
    slab = Array.make 4 0.;
    hits = { h = Array.make (64 * hit_width) 0. };
    leaf = [| -1 |];
    qhits = Array.make max_hits 0.;
    torus = Torus.create_work ();
    ghits = { h = Array.make 64 0. };
    near = Array.make 5 0.;
    walk_lim = [| 0. |];
    best = { best_id = -1; best_face = -1 };
  }
let black = { r = 0.; g = 0.; b = 0.; tr = 0. }

(* ---------------------------------------------------------------------------------------------- *)
(* Intersections *)

(* The nearest depth of [shape] along the ray that is inside the shape's own limits and at least
   [lo], or infinity; for a mesh the face is left in [ctx.sub.(0)]. *)
(* §2.2: the nearer root of the sphere (cx, cy, cz, r²) within the limits, or infinity. *)
let[@inline] sphere_depth (stats : Stats.t) (lim : Limits.t) cx cy cz r2 (o : Vec.t) (d : Vec.t) lo =
  stats.sphere_tests <- stats.sphere_tests + 1;
  let ocx = cx -. o.x and ocy = cy -. o.y and ocz = cz -. o.z in
  let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. d.x) +. (ocy *. d.y) +. (ocz *. d.z) in
  if ocs >= r2 && tca < lim.tangent then infinity
  else
    let h2 = r2 -. ocs +. (tca *. tca) in
    if h2 <= lim.tangent then infinity
    else begin
      let h = sqrt h2 in
      let t1 = tca -. h in
      if t1 > lim.near && t1 < lim.far && t1 >= lo then (stats.sphere_hits <- stats.sphere_hits + 1; t1)
      else
        let t2 = tca +. h in
        if t2 > lim.near && t2 < lim.far && t2 >= lo then (stats.sphere_hits <- stats.sphere_hits + 1; t2)
        else infinity
    end

(* §2.2, §14.5 (b): the ellipsoid [s] mapped by [t]: the ray is brought into object space with
   its direction renormalised; the roots are limited in object units and divided by the length
   of the object-space direction. Everything stays in unboxed floats. *)
let ellipsoid_depth (stats : Stats.t) (lim : Limits.t) (s : sphere) (t : Transform.t) (o : Vec.t) (d : Vec.t) lo =
  stats.sphere_tests <- stats.sphere_tests + 1;
  let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
  let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
  let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  let len = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  (* VInverseScaleEq: times the reciprocal *)
  let k = 1. /. len in
  let vx = vx *. k and vy = vy *. k and vz = vz *. k in
  let ocx = s.cx -. px and ocy = s.cy -. py and ocz = s.cz -. pz in
  let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. vx) +. (ocy *. vy) +. (ocz *. vz) in
  if ocs >= s.r2 && tca < lim.tangent then infinity
  else
    let h2 = s.r2 -. ocs +. (tca *. tca) in
    if h2 <= lim.tangent then infinity
    else begin
      let h = sqrt h2 in
      let t1 = tca -. h in
      if t1 > lim.near && t1 < lim.far && t1 /. len >= lo then (stats.sphere_hits <- stats.sphere_hits + 1; t1 /. len)
      else
        let t2 = tca +. h in
        if t2 > lim.near && t2 < lim.far && t2 /. len >= lo then (stats.sphere_hits <- stats.sphere_hits + 1; t2 /. len)
        else infinity
    end

(* §2.3, §14.5 (a): the plane [p] mapped by [t]: the ray in object space, direction NOT
   renormalised, so the depth is the world depth and the limits apply to it. *)
let plane_trans_depth (stats : Stats.t) (lim : Limits.t) (p : plane) (t : Transform.t) (o : Vec.t) (d : Vec.t) lo =
  stats.plane_tests <- stats.plane_tests + 1;
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  let ndd = (p.nx *. vx) +. (p.ny *. vy) +. (p.nz *. vz) in
  if Float.abs ndd < epsilon then infinity
  else
    let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
    let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
    let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
    let ndo = (p.nx *. px) +. (p.ny *. py) +. (p.nz *. pz) in
    let t = -.(ndo +. p.dist) /. ndd in
    if t >= lim.near && t <= lim.far && t >= lo then (stats.plane_hits <- stats.plane_hits + 1; t)
    else infinity

(* §15.1, Box::Intersect, §14.5 (a): the slabs of the box [b] crossed by the ray from (px, py, pz)
   along (vx, vy, vz), not renormalised, so depths are world depths. The X slab uses exact
   comparisons; the Y and Z slabs keep the side already found when a crossing is within
   [ctx.lim.close] (1e-6) of it,
   unless the ray is steeper towards the new side. Sides are 1–6 for X−, X+, Y−, Y+, Z−, Z+ (0: none
   yet). Whether the box is hit (the far crossing beyond the near limit); the crossings and their
   sides are left in [ctx.slab]. The near crossing counts beyond the near limit, the far one
   always. *)
let box_slabs ctx (b : box) px py pz vx vy vz =
  let stats = ctx.stats in
  stats.box_tests <- stats.box_tests + 1;
  let box_close = ctx.lim.close in
  let tmin = ref 0. and tmax = ref 2e10 and smin = ref 0 and smax = ref 0 and miss = ref false in
  if vx < -.epsilon || vx > epsilon then begin
    let neg = vx < 0. in
    let t = ((if neg then b.x0 else b.x1) -. px) /. vx in
    if t < !tmin then miss := true
    else begin
      if t <= !tmax then begin smax := (if neg then 1 else 2); tmax := t end;
      let t = ((if neg then b.x1 else b.x0) -. px) /. vx in
      if t >= !tmin then if t > !tmax then miss := true else begin smin := (if neg then 2 else 1); tmin := t end
    end
  end
  else if px < b.x0 || px > b.x1 then miss := true;
  if not !miss then
    if vy < -.epsilon || vy > epsilon then begin
      let neg = vy < 0. in
      let steeper = Float.abs vy > Float.abs vx in
      let t = ((if neg then b.y0 else b.y1) -. py) /. vy in
      if t < !tmin then miss := true
      else begin
        if t <= !tmax -. box_close then begin smax := (if neg then 3 else 4); tmax := t end
        else if t <= !tmax +. box_close && steeper then smax := (if neg then 3 else 4);
        let t = ((if neg then b.y1 else b.y0) -. py) /. vy in
        if t >= !tmin +. box_close then (if t > !tmax then miss := true else begin smin := (if neg then 4 else 3); tmin := t end)
        else if t >= !tmin -. box_close && steeper then smin := (if neg then 4 else 3)
      end
    end
    else if py < b.y0 || py > b.y1 then miss := true;
  if not !miss then
    if vz < -.epsilon || vz > epsilon then begin
      let neg = vz < 0. in
      let az = Float.abs vz in
      let steeper_x = az > Float.abs vx and steeper_y = az > Float.abs vy in
      let t = ((if neg then b.z0 else b.z1) -. pz) /. vz in
      if t < !tmin then miss := true
      else begin
        let s = !smax in
        if t <= !tmax -. box_close then begin smax := (if neg then 5 else 6); tmax := t end
        else if t <= !tmax +. box_close && (((s = 1 || s = 2) && steeper_x) || ((s = 3 || s = 4) && steeper_y)) then
          smax := (if neg then 5 else 6);
        let s = !smin in
        let t = ((if neg then b.z1 else b.z0) -. pz) /. vz in
        if t >= !tmin +. box_close then (if t > !tmax then miss := true else begin smin := (if neg then 6 else 5); tmin := t end)
        else if t >= !tmin -. box_close && (((s = 1 || s = 2) && steeper_x) || ((s = 3 || s = 4) && steeper_y)) then
          smin := (if neg then 6 else 5)
      end
    end
    else if pz < b.z0 || pz > b.z1 then miss := true;
  ctx.slab.(0) <- !tmin;
  ctx.slab.(1) <- !tmax;
  ctx.slab.(2) <- Float.of_int !smin;
  ctx.slab.(3) <- Float.of_int !smax;
  not (!miss || !tmax < ctx.lim.near)

(* The nearest crossing of the box at least [lo] (see [box_slabs]); its side in [ctx.sub.(0)]. *)
let box_depth ctx (b : box) px py pz vx vy vz lo =
  if not (box_slabs ctx b px py pz vx vy vz) then infinity
  else
    let stats = ctx.stats and tmin = ctx.slab.(0) and tmax = ctx.slab.(1) in
    if tmin > ctx.lim.near && tmin >= lo && (tmin < tmax || tmax < lo) then begin
      (* both crossings are candidates, the far one pushed last; POV-Ray takes candidates from the
         top of its stack and keeps a strictly nearer one, so of two equal depths (a ray through an
         edge) the far crossing's side wins *)
      stats.box_hits <- stats.box_hits + 1;
      ctx.sub.(0) <- int_of_float ctx.slab.(2);
      tmin
    end
    else if tmax >= lo then begin
      stats.box_hits <- stats.box_hits + 1;
      ctx.sub.(0) <- int_of_float ctx.slab.(3);
      tmax
    end
    else infinity

(* §15.1: the box [b] mapped by [t]: the ray brought into object space, direction not renormalised. *)
let box_trans_depth ctx (b : box) (t : Transform.t) (o : Vec.t) (d : Vec.t) lo =
  let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
  let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
  let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  box_depth ctx b px py pz vx vy vz lo

(* §15.2, §15.3: cylinders and cones reject canonical depths up to Cone_Tolerance (1e-9) *)
let cone_tolerance = 1e-9

(* The parts of a cylinder or cone a hit can be on (§15.2): POV-Ray's BASE_HIT, CAP_HIT, SIDE_HIT. *)
let base_hit = 1
let cap_hit = 2
let side_hit = 3

(* §15.2, §15.3, Cone::Intersect, §14.5 (b): every crossing of the ray from [o] along the unit [d]
   with the cylinder or cone [c], in POV-Ray's order (the side's two roots, then the cap at z = 1,
   then the base at z = dist), written into [out] as pairs (world depth, part: 1 base, 2 cap,
   3 side); returns how many. The ray is brought into canonical space with its direction
   renormalised; depths are limited there (1e-9 < s < 1e7) and divided by the direction's length.
   [out] needs room for 8 floats. Nothing is allocated. *)
let[@inline] put (out : float array) n depth part =
  out.(2 * n) <- depth;
  out.((2 * n) + 1) <- part;
  n + 1

let cone_hits ctx (c : cone) (o : Vec.t) (d : Vec.t) (out : float array) =
  let stats = ctx.stats in
  stats.cone_tests <- stats.cone_tests + 1;
  let t = c.ctr in
  let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
  let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
  let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  let len = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  (* VInverseScaleEq: times the reciprocal *)
  let k = 1. /. len in
  let vx = vx *. k and vy = vy *. k and vz = vz *. k in
  let near = if ctx.robust then 0. else cone_tolerance and far = ctx.lim.far in
  let side = float_of_int side_hit in
  let n =
    if c.cyl then begin
      let a = (vx *. vx) +. (vy *. vy) in
      if a > epsilon then begin
        let b = (px *. vx) +. (py *. vy) in
        let cc = (px *. px) +. (py *. py) -. 1.0 in
        let dsc = (b *. b) -. (a *. cc) in
        if dsc >= 0.0 then begin
          let sq = sqrt dsc in
          (* the far root first, as Cone::Intersect lists them *)
          let t1 = (-.b +. sq) /. a and t2 = (-.b -. sq) /. a in
          let z1 = pz +. (t1 *. vz) and z2 = pz +. (t2 *. vz) in
          let n = if t1 > near && t1 < far && z1 >= 0.0 && z1 <= 1.0 then put out 0 (t1 /. len) side else 0 in
          if t2 > near && t2 < far && z2 >= 0.0 && z2 <= 1.0 then put out n (t2 /. len) side else n
        end
        else 0
      end
      else 0
    end
    else begin
      let a = (vx *. vx) +. (vy *. vy) -. (vz *. vz) in
      let b = (vx *. px) +. (vy *. py) -. (vz *. pz) in
      let cc = (px *. px) +. (py *. py) -. (pz *. pz) in
      if Float.abs a < epsilon then begin
        (* the ray parallel to a generator: one crossing *)
        if Float.abs b > epsilon then begin
          let t1 = -0.5 *. cc /. b in
          let z1 = pz +. (t1 *. vz) in
          if t1 > near && t1 < far && z1 >= c.dist && z1 <= 1.0 then put out 0 (t1 /. len) side else 0
        end
        else 0
      end
      else begin
        let dsc = (b *. b) -. (a *. cc) in
        if dsc >= 0.0 then begin
          let sq = sqrt dsc in
          let t1 = (-.b -. sq) /. a and t2 = (-.b +. sq) /. a in
          let z1 = pz +. (t1 *. vz) and z2 = pz +. (t2 *. vz) in
          let n = if t1 > near && t1 < far && z1 >= c.dist && z1 <= 1.0 then put out 0 (t1 /. len) side else 0 in
          if t2 > near && t2 < far && z2 >= c.dist && z2 <= 1.0 then put out n (t2 /. len) side else n
        end
        else 0
      end
    end
  in
  let n =
    if c.closed && Float.abs vz > epsilon then begin
      let s1 = (1.0 -. pz) /. vz in
      let a1 = px +. (s1 *. vx) and b1 = py +. (s1 *. vy) in
      let n = if (a1 *. a1) +. (b1 *. b1) <= 1.0 && s1 > near && s1 < far then put out n (s1 /. len) (float_of_int cap_hit) else n in
      let s2 = (c.dist -. pz) /. vz in
      let a2 = px +. (s2 *. vx) and b2 = py +. (s2 *. vy) in
      let r2 = if c.cyl then 1.0 else c.dist *. c.dist in
      if (a2 *. a2) +. (b2 *. b2) <= r2 && s2 > near && s2 < far then put out n (s2 /. len) (float_of_int base_hit) else n
    end
    else n
  in
  if n > 0 then stats.cone_hits <- stats.cone_hits + 1;
  n

(* §15.4, Disc::Intersect, §14.5 (b): the crossing of the ray with the disc [dc], written into
   [out] as (world depth, 0); returns 0 or 1. The plane's crossing must be ahead in canonical
   units (s ≥ 0), within the ring (hole² ≤ r² ≤ radius²), and its world depth within the limits
   (1e-6 < depth < 1e7). *)
let disc_hits ctx (dc : disc) (o : Vec.t) (d : Vec.t) (out : float array) =
  let stats = ctx.stats in
  stats.disc_tests <- stats.disc_tests + 1;
  let t = dc.dtr in
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  let len = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  let k = 1. /. len in
  let vx = vx *. k and vy = vy *. k and vz = vz *. k in
  if Float.abs vz > epsilon then begin
    let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
    let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
    let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
    let s = -.pz /. vz in
    if s >= 0.0 then begin
      let u = px +. (s *. vx) and v = py +. (s *. vy) in
      let r2 = (u *. u) +. (v *. v) in
      if r2 >= dc.ir2 && r2 <= dc.or2 then begin
        let depth = s /. len in
        if depth > ctx.lim.near && depth < ctx.lim.far then begin
          stats.disc_hits <- stats.disc_hits + 1;
          put out 0 depth 0.
        end
        else 0
      end
      else 0
    end
    else 0
  end
  else 0

(* The nearest of the [n] hits in [ctx.qhits] at least [lo], its part left in [ctx.sub.(0)]; or
   infinity. POV-Ray takes them from the top of its intersection stack, the last found first,
   keeping a strictly nearer one: of equal depths the last found wins. *)
let nearest_listed ctx n lo =
  let h = ctx.qhits in
  let best = ref infinity and part = ref 0 in
  for i = n - 1 downto 0 do
    let t = h.(2 * i) in
    if t < !best && t >= lo then begin
      best := t;
      part := int_of_float h.((2 * i) + 1)
    end
  done;
  if !best < infinity then ctx.sub.(0) <- !part;
  !best

(* §15.5: one torus intersection, counted as POV-Ray counts it ("Torus", "Torus Bound", "Roots
   tested … eliminated"); the raw depths are left in the torus work room. *)
let torus_solve ctx (t : Torus.t) (o : Vec.t) (d : Vec.t) =
  let stats = ctx.stats in
  stats.torus_tests <- stats.torus_tests + 1;
  let n = Torus.solve ctx.torus t o d in
  if n >= 0 then begin
    stats.torus_bound_hits <- stats.torus_bound_hits + 1;
    stats.roots_tested <- stats.roots_tested + 1;
    if Torus.eliminated ctx.torus then stats.roots_eliminated <- stats.roots_eliminated + 1;
    if n > 0 then stats.torus_hits <- stats.torus_hits + 1
  end;
  n

(* the torus's own depth limit, 1e-4 in world units (§15.5); the robust mode takes every depth *)
let torus_near ctx = if ctx.robust then 0. else Torus.depth_tolerance

let torus_hits ctx t o d out =
  let n = torus_solve ctx t o d in
  let near = torus_near ctx and ds = Torus.depths ctx.torus in
  let k = ref 0 in
  for i = 0 to n - 1 do
    let x = ds.(i) in
    if x > near && x < 1e7 then begin
      out.(!k) <- x;
      incr k
    end
  done;
  !k

(* §15.5: the nearest of a torus's depths within its limits and at least [lo] *)
let torus_depth ctx t o d lo =
  let n = torus_solve ctx t o d in
  let near = torus_near ctx and ds = Torus.depths ctx.torus in
  let best = ref infinity in
  for i = 0 to n - 1 do
    let x = ds.(i) in
    if x > near && x < 1e7 && x >= lo && x < !best then best := x
  done;
  !best

(* §15.9: every crossing of a text letter, counted as POV-Ray counts them ("True Type Font"
   tests and successes); the (depth, part) pairs are left in [ctx.ghits]. *)
let glyph_hits ctx (g : Glyph.t) (o : Vec.t) (d : Vec.t) =
  let stats = ctx.stats in
  stats.ttf_tests <- stats.ttf_tests + 1;
  let room = Glyph.max_hits g.outline in
  if Array.length ctx.ghits.h < room then ctx.ghits.h <- Array.make room 0.;
  let k = Glyph.hits g o d ctx.ghits.h in
  if k > 0 then stats.ttf_hits <- stats.ttf_hits + 1;
  k

(* the nearest crossing at least [lo], the first of equal ones, its part left in [ctx.sub] *)
let glyph_depth ctx g o d lo =
  let k = glyph_hits ctx g o d in
  let h = ctx.ghits.h in
  let best = ref infinity and part = ref 0 in
  for i = 0 to k - 1 do
    let t = h.(2 * i) in
    if t >= lo && t < !best then begin
      best := t;
      part := int_of_float h.((2 * i) + 1)
    end
  done;
  if !best < infinity then ctx.sub.(0) <- !part;
  !best

(* Where the ray enters POV-Ray's box [b] of an object (Check_And_Enqueue, with the ray as Rayinfo
   holds it: origin and reciprocal direction in single precision, and the slab arithmetic in single
   precision too), or infinity when it misses the box. *)
let pov_entry (b : float array) (o : Vec.t) (d : Vec.t) =
  let bound_huge = 2e10 in
  let exception Miss in
  let slab ll len on dn =
    (* the interval of the slab along the ray, or None for a direction parallel to it *)
    if dn <> 0. then begin
      let sd = f32 (1. /. dn) in
      let near = f32 (f32 (ll -. f32 on) *. sd) in
      let span = f32 (len *. sd) in
      Some (if dn > 0. then (near, near +. span) else (near +. span, near))
    end
    else
      let sn = f32 on in
      if sn < ll || sn > f32 (len +. ll) then raise Miss else None
  in
  try
    let dmin, dmax =
      match slab b.(0) b.(3) o.x d.x with
      | Some (lo, hi) -> if hi < epsilon || lo > hi then raise Miss else (lo, hi)
      | None -> (-.bound_huge, bound_huge)
    in
    let narrow ~last (dmin, dmax) = function
      | None -> (dmin, dmax)
      | Some (tmin, tmax) ->
          if tmax < dmax then begin
            if tmax < epsilon then raise Miss;
            let dmin =
              if tmin > dmin then (if tmin > tmax then raise Miss; tmin) else if dmin > tmax then raise Miss else dmin
            in
            (* the Z step does not lower dmax: it is not used afterwards *)
            (dmin, if last then dmax else tmax)
          end
          else if tmin > dmin then (if tmin > dmax then raise Miss; (tmin, dmax))
          else (dmin, dmax)
    in
    let r = narrow ~last:false (dmin, dmax) (slab b.(1) b.(4) o.y d.y) in
    fst (narrow ~last:true r (slab b.(2) b.(5) o.z d.z))
  with Miss -> infinity

let rec hit_shape ctx shape (o : Vec.t) (d : Vec.t) lo =
  let stats = ctx.stats in
  match shape with
  | Csg c ->
      (* Trace::FindIntersection tests a CSG's single-precision box first (§15.8): a ray grazing
         an edge of the box within its rounding misses the CSG. The robust mode decides by the
         geometry alone. *)
      if (not ctx.robust) && Array.length c.cbox > 0 && pov_entry c.cbox o d = infinity then infinity else csg_depth ctx c o d lo
  | Sphere s -> sphere_depth stats ctx.lim s.cx s.cy s.cz s.r2 o d lo
  | Ellipsoid { sp; etr } -> ellipsoid_depth stats ctx.lim sp etr o d lo
  | Plane p ->
      (* §2.3 *)
      stats.plane_tests <- stats.plane_tests + 1;
      let ndd = (p.nx *. d.x) +. (p.ny *. d.y) +. (p.nz *. d.z) in
      if Float.abs ndd < epsilon then infinity
      else
        let ndo = (p.nx *. o.x) +. (p.ny *. o.y) +. (p.nz *. o.z) in
        let t = -.(ndo +. p.dist) /. ndd in
        if t >= ctx.lim.near && t <= ctx.lim.far && t >= lo then (stats.plane_hits <- stats.plane_hits + 1; t)
        else infinity
  | Plane_trans { pl; ptr; _ } -> plane_trans_depth stats ctx.lim pl ptr o d lo
  | Box b -> box_depth ctx b o.x o.y o.z d.x d.y d.z lo
  | Box_trans { bx; btr } -> box_trans_depth ctx bx btr o d lo
  | Cone c -> nearest_listed ctx (cone_hits ctx c o d ctx.qhits) lo
  | Disc dc -> nearest_listed ctx (disc_hits ctx dc o d ctx.qhits) lo
  | Torus t -> torus_depth ctx t o d lo
  | Glyph g -> glyph_depth ctx g o d lo
  | Triangle t | Smooth_triangle t ->
      (* §2.4 *)
      stats.triangle_tests <- stats.triangle_tests + 1;
      let depth = Triangle.intersect_within ctx.lim t o d in
      if depth >= lo && depth < infinity then (stats.triangle_hits <- stats.triangle_hits + 1; depth) else infinity
  | Mesh m ->
      (* §2.6, Mesh::Intersect: a moved mesh is searched in its own space with the direction
         renormalised (times the reciprocal length), and the depth is divided by that length *)
      stats.mesh_tests <- stats.mesh_tests + 1;
      let k, depth =
        if not m.moved then
          let k = Mesh.nearest_within ctx.lim m.mesh ctx.mstack o d lo ctx.depth in
          (k, ctx.depth.(0))
        else
          let v = Transform.inv_direction m.tr d in
          let len = Vec.length v in
          let k = Mesh.nearest_within ctx.lim m.mesh ctx.mstack (Transform.inv_point m.tr o) (Vec.scale (1. /. len) v) (lo *. len) ctx.depth in
          (k, ctx.depth.(0) /. len)
      in
      if k >= 0 && depth >= lo then begin
        stats.mesh_hits <- stats.mesh_hits + 1;
        ctx.sub.(0) <- k;
        depth
      end
      else infinity

(* ---------------------------------------------------------------------------------------------- *)
(* CSG (§16.2): every crossing of every member, kept by the CSG's rule *)

(* Appends a hit of the leaf [id] at depth [t] (side or face [sub]) at the point (px, py, pz) to
   the scratch after [n] hits; returns the new count. *)
and push_hit ctx n t sub id px py pz =
  let w = hit_width in
  if (n + 1) * w > Array.length ctx.hits.h then begin
    let bigger = Array.make (2 * Array.length ctx.hits.h) 0. in
    Array.blit ctx.hits.h 0 bigger 0 (n * w);
    ctx.hits.h <- bigger
  end;
  let h = ctx.hits.h and j = n * w in
  h.(j) <- t;
  h.(j + 1) <- Float.of_int sub;
  h.(j + 2) <- Float.of_int id;
  h.(j + 3) <- px;
  h.(j + 4) <- py;
  h.(j + 5) <- pz;
  n + 1

(* A world-space hit at depth [t] along the ray, if at least [lo]. *)
and push_ray ctx n lo t sub id (o : Vec.t) (d : Vec.t) =
  if t >= lo then push_hit ctx n t sub id (o.x +. (t *. d.x)) (o.y +. (t *. d.y)) (o.z +. (t *. d.z)) else n

(* Every crossing at least [lo] of the object [ob] (a primitive or a CSG) along the ray, appended
   after the [n] hits in the scratch in the order POV-Ray's All_Intersections pushes them; returns
   the new count. A new primitive shape gets its case here. *)
and all_hits ctx (ob : obj) (o : Vec.t) (d : Vec.t) lo n =
  let stats = ctx.stats and lim = ctx.lim and id = ob.id in
  match ob.shape with
  | Csg c -> csg_hits ctx c o d lo n
  | Sphere s ->
      (* Sphere::All_Intersections: both roots within the limits *)
      stats.sphere_tests <- stats.sphere_tests + 1;
      let ocx = s.cx -. o.x and ocy = s.cy -. o.y and ocz = s.cz -. o.z in
      let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
      let tca = (ocx *. d.x) +. (ocy *. d.y) +. (ocz *. d.z) in
      if ocs >= s.r2 && tca < lim.tangent then n
      else
        let h2 = s.r2 -. ocs +. (tca *. tca) in
        if h2 <= lim.tangent then n
        else
          let h = sqrt h2 in
          let t1 = tca -. h and t2 = tca +. h in
          let n0 = n in
          let n = if t1 > lim.near && t1 < lim.far then push_ray ctx n lo t1 (-1) id o d else n in
          let n = if t2 > lim.near && t2 < lim.far then push_ray ctx n lo t2 (-1) id o d else n in
          if n > n0 then stats.sphere_hits <- stats.sphere_hits + 1;
          n
  | Ellipsoid { sp = s; etr = t } ->
      (* in object space, the direction renormalised; the hit point is the object-space point
         mapped back *)
      stats.sphere_tests <- stats.sphere_tests + 1;
      let q = Transform.inv_point t o and v = Transform.inv_direction t d in
      let len = Vec.length v in
      let k = 1. /. len in
      let v = Vec.scale k v in
      let ocx = s.cx -. q.x and ocy = s.cy -. q.y and ocz = s.cz -. q.z in
      let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
      let tca = (ocx *. v.x) +. (ocy *. v.y) +. (ocz *. v.z) in
      if ocs >= s.r2 && tca < lim.tangent then n
      else
        let h2 = s.r2 -. ocs +. (tca *. tca) in
        if h2 <= lim.tangent then n
        else
          let h = sqrt h2 in
          let root n t0 =
            if t0 > lim.near && t0 < lim.far && t0 /. len >= lo then
              let p = Transform.point t (Vec.madd q t0 v) in
              push_hit ctx n (t0 /. len) (-1) id p.x p.y p.z
            else n
          in
          let n0 = n in
          let n = root (root n (tca -. h)) (tca +. h) in
          if n > n0 then stats.sphere_hits <- stats.sphere_hits + 1;
          n
  | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ ->
      (* one crossing at most *)
      let t = hit_shape ctx ob.shape o d lo in
      if t < infinity then push_ray ctx n lo t (-1) id o d else n
  | Box b ->
      if box_slabs ctx b o.x o.y o.z d.x d.y d.z then box_pair ctx n lo id o d else n
  | Box_trans { bx; btr = t } ->
      let q = Transform.inv_point t o and v = Transform.inv_direction t d in
      if box_slabs ctx bx q.x q.y q.z v.x v.y v.z then box_pair ctx n lo id o d else n
  | Mesh m ->
      stats.mesh_tests <- stats.mesh_tests + 1;
      let count = ref n in
      let n0 = n in
      (if not m.moved then Mesh.iter_hits lim m.mesh ctx.mstack o d (fun k t -> count := push_ray ctx !count lo t k id o d)
       else
         let v = Transform.inv_direction m.tr d in
         let len = Vec.length v in
         Mesh.iter_hits lim m.mesh ctx.mstack (Transform.inv_point m.tr o) (Vec.scale (1. /. len) v) (fun k t ->
             count := push_ray ctx !count lo (t /. len) k id o d));
      if !count > n0 then stats.mesh_hits <- stats.mesh_hits + 1;
      !count

  | Cone c ->
      (* Cone::All_Intersections: the listed crossings in their order, each with its part *)
      let k = cone_hits ctx c o d ctx.qhits in
      let q = ctx.qhits in
      let n = ref n in
      for i = 0 to k - 1 do
        n := push_ray ctx !n lo q.(2 * i) (int_of_float q.((2 * i) + 1)) id o d
      done;
      !n
  | Disc dc ->
      let k = disc_hits ctx dc o d ctx.qhits in
      if k > 0 then push_ray ctx n lo ctx.qhits.(0) 0 id o d else n
  | Torus t ->
      (* Torus::All_Intersections: the roots within the limits, in the solver's order *)
      let k = torus_hits ctx t o d ctx.qhits in
      let n = ref n in
      for i = 0 to k - 1 do
        n := push_ray ctx !n lo ctx.qhits.(i) (-1) id o d
      done;
      !n
  | Glyph g ->
      (* TrueType::All_Intersections: the faces, then the walls, in the order found *)
      let k = glyph_hits ctx g o d in
      let n = ref n in
      for i = 0 to k - 1 do
        let h = ctx.ghits.h in
        n := push_ray ctx !n lo h.(2 * i) (int_of_float h.((2 * i) + 1)) id o d
      done;
      !n

(* Box::All_Intersections: the near crossing beyond the near limit, then the far one. *)
and box_pair ctx n lo id o d =
  let tmin = ctx.slab.(0) and tmax = ctx.slab.(1) in
  let smin = int_of_float ctx.slab.(2) and smax = int_of_float ctx.slab.(3) in
  ctx.stats.box_hits <- ctx.stats.box_hits + 1;
  let n = if tmin > ctx.lim.near then push_ray ctx n lo tmin smin id o d else n in
  push_ray ctx n lo tmax smax id o d

(* Keeps the hits [start, e) of member [skip] whose point is Inside ([want]) or outside every other
   member, in place; [reverse]d when they come off a local stack. Returns the new end. *)
and keep_hits ctx (members : obj array) ~skip ~want ~reverse start e =
  let nm = Array.length members in
  let w = ref start in
  for j = start to e - 1 do
    let h = ctx.hits.h and b = j * hit_width in
    let p = Vec.make h.(b + 3) h.(b + 4) h.(b + 5) in
    let keep = ref true and i = ref 0 in
    while !keep && !i < nm do
      if !i <> skip && Compile.inside_member ctx.mstack members.(!i) p <> want then keep := false;
      incr i
    done;
    if !keep then begin
      if !w <> j then Array.blit h b h (!w * hit_width) hit_width;
      incr w
    end
  done;
  if reverse then begin
    let h = ctx.hits.h in
    let a = ref start and z = ref (!w - 1) in
    while !a < !z do
      for f = 0 to hit_width - 1 do
        let x = h.((!a * hit_width) + f) in
        h.((!a * hit_width) + f) <- h.((!z * hit_width) + f);
        h.((!z * hit_width) + f) <- x
      done;
      incr a;
      decr z
    done
  end;
  !w

(* §16.2: a union keeps every hit of its members; an intersection a hit of member k whose point
   is inside every other member; a merge one inside no other member. A member's surviving hits
   are taken off its own stack, so they are pushed in reverse (intersection and merge). A clipped
   object keeps its hits inside every clip object, in the order it pushes them (Point_In_Clip);
   a clipped union, like an intersection, takes each member's hits off a stack of its own. *)
and csg_hits ctx (c : csg) o d lo n =
  let stats = ctx.stats and n0 = n in
  let members = c.members in
  let nm = Array.length members in
  let n =
    match c.kind with
    | Union ->
        stats.csg_union_tests <- stats.csg_union_tests + 1;
        let n = ref n in
        Array.iter (fun m -> n := all_hits ctx m o d lo !n) members;
        !n
    | Intersection | Merge ->
        (match c.kind with
        | Intersection -> stats.csg_intersection_tests <- stats.csg_intersection_tests + 1
        | Merge | Union | Clipped -> stats.csg_merge_tests <- stats.csg_merge_tests + 1);
        let want = match c.kind with Intersection -> true | Merge | Union | Clipped -> false in
        let n = ref n in
        for k = 0 to nm - 1 do
          let start = !n in
          let e = all_hits ctx members.(k) o d lo start in
          n := keep_hits ctx members ~skip:k ~want ~reverse:true start e
        done;
        !n
    | Clipped when nm = 0 -> n
    | Clipped -> (
        match members.(0).shape with
        | Csg { kind = Union; members = um; _ } ->
            stats.csg_union_tests <- stats.csg_union_tests + 1;
            let n = ref n in
            Array.iter
              (fun u ->
                let start = !n in
                let e = all_hits ctx u o d lo start in
                n := keep_hits ctx members ~skip:0 ~want:true ~reverse:true start e)
              um;
            if !n > n0 then stats.csg_union_hits <- stats.csg_union_hits + 1;
            !n
        | Csg { kind = Merge | Intersection | Clipped; _ }
        | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ ->
            let e = all_hits ctx members.(0) o d lo n in
            keep_hits ctx members ~skip:0 ~want:true ~reverse:false n e)
  in
  (if n > n0 then
     match c.kind with
     | Union -> stats.csg_union_hits <- stats.csg_union_hits + 1
     | Intersection -> stats.csg_intersection_hits <- stats.csg_intersection_hits + 1
     | Merge -> stats.csg_merge_hits <- stats.csg_merge_hits + 1
     | Clipped -> ());
  n

(* §16.2: the nearest hit of a top-level CSG: its hits are popped from the stack, last pushed
   first, and the first of the smallest depth wins. The leaf hit is left in [ctx.leaf.(0)], its
   side or face in [ctx.sub.(0)]. *)
and csg_depth ctx (c : csg) o d lo =
  let n = csg_hits ctx c o d lo 0 in
  let h = ctx.hits.h in
  let best = ref infinity and bj = ref (-1) in
  for j = n - 1 downto 0 do
    let t = h.(j * hit_width) in
    if t < !best then begin best := t; bj := j end
  done;
  if !bj >= 0 then begin
    ctx.sub.(0) <- int_of_float h.((!bj * hit_width) + 1);
    ctx.leaf.(0) <- int_of_float h.((!bj * hit_width) + 2)
  end;
  !best

(* Whether [ob], hit at exactly the depth of the current best [cur], replaces it: POV-Ray keeps the
   first of equal depths it meets. Without its bounding hierarchy it tests the objects in scene
   order. With it, it tests planes first, then bounded objects in the order the ray enters their
   boxes; so of two bounded objects the one whose box is entered first wins. (Among planes, the
   order of its priority queue is not modelled: the first found is kept.) *)
let wins_tie ctx ob cur (o : Vec.t) (d : Vec.t) =
  if not ctx.scene.bounding then ob.id < cur
  else
    (* [cur] may be a CSG member: its top-level object's box counts *)
    let pb = ctx.scene.objects.(ctx.scene.objects.(cur).top).pbox in
    if Array.length pb = 0 then false
    else Array.length ob.pbox = 0 || pov_entry ob.pbox o d < pov_entry pb o d

(* The robust mode's ties: depths this close (relative to the ray's origin and length) differ only
   by rounding, as on coplanar surfaces, and the object written first wins, whatever the scene's
   size or place. *)
let tie_tolerance (o : Vec.t) t = 0x1p-36 *. (Float.max (Float.abs o.x) (Float.max (Float.abs o.y) (Float.abs o.z)) +. t)

(* Whether POV-Ray's bounding tree would never have tested [ob], nearer than the current best
   [best] by rounding only: it takes objects in the order the ray enters their single-precision
   boxes and stops at the first box entered beyond the best depth found so far. So where a box
   stands on a plane, a ray meeting the box's face exactly at the plane sees the plane. Asked only
   of near ties. *)
let pruned ctx ob t best cur (o : Vec.t) (d : Vec.t) =
  ctx.scene.bounding && cur >= 0
  && t > best -. (1e-9 *. Float.abs best)
  && Array.length ob.pbox > 0
  && pov_entry ob.pbox o d > best

(* The converse of [pruned]: whether [ob], hit just beyond the current best [cur] (farther by
   rounding only), is what POV-Ray finds. Its bounding tree enters [ob]'s box first, takes [ob]'s
   hit as the best, and then never tests [cur], whose box it enters beyond that depth. So where a
   glass cylinder stands on a glass box, a ray inside the cylinder sees the cylinder's end rather
   than the box's face 1 unit in the last place nearer. Asked only of near ties. *)
let overtakes ctx ob t best cur (o : Vec.t) (d : Vec.t) =
  ctx.scene.bounding && cur >= 0
  && t < best +. (1e-9 *. Float.abs best)
  && Array.length ob.pbox > 0
  &&
  let pb = ctx.scene.objects.(ctx.scene.objects.(cur).top).pbox in
  Array.length pb > 0
  &&
  let ec = pov_entry pb o d in
  ec > t && pov_entry ob.pbox o d < ec

(* Whether [ob], hit at depth [t], replaces the current best [cur] at depth [best]. *)
let[@inline] replaces ctx ob t best cur (o : Vec.t) (d : Vec.t) =
  if not ctx.robust then
    (t < best && not (pruned ctx ob t best cur o d))
    || (t = best && cur >= 0 && wins_tie ctx ob cur o d)
    || (t > best && overtakes ctx ob t best cur o d)
  else if cur < 0 then t < best
  else
    let tol = tie_tolerance o best in
    t < best -. tol || (t <= best +. tol && ob.id < cur)

(* the slab test's min and max (as the hierarchy's: no −0 or NaN ordering, no C call) *)
let[@inline] fmin (a : float) b = if a < b then a else b
let[@inline] fmax (a : float) b = if a > b then a else b
let[@inline] recip x = if x = 0. then 1e300 else 1. /. x

(* The ray of one call of [nearest] and what it searches, for its visitor (a toplevel function,
   so that no closure is built per call); immutable, so that building it needs no write barrier. *)
type search = { sctx : ctx; sgroup : group; so : Vec.t; sd : Vec.t }

(* [nearest]'s test of the object [ob], the best so far in [ctx.best] and [ctx.near] *)
let try_obj ctx ob (o : Vec.t) (d : Vec.t) =
  let r = ctx.best and nr = ctx.near in
  let t = hit_shape ctx ob.shape o d nr.(4) in
  if replaces ctx ob t nr.(0) r.best_id o d then begin
    nr.(0) <- t;
    (* a CSG reports the member hit *)
    r.best_id <- (match ob.shape with Csg _ -> ctx.leaf.(0) | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ -> ob.id);
    r.best_face <- ctx.sub.(0)
  end

(* [nearest]'s visitor of the bounded object [i] met by the walk *)
let visit_bounded st i =
  let ctx = st.sctx and g = st.sgroup and o = st.so and d = st.sd in
  let r = ctx.best and nr = ctx.near in
  let sp = g.spheres and bx = g.boxes in
  let r2 = Array.unsafe_get sp ((4 * i) + 3) in
  if r2 = r2 then begin
    (* a sphere, straight from the flat array *)
    let t = sphere_depth ctx.stats ctx.lim (Array.unsafe_get sp (4 * i)) (Array.unsafe_get sp ((4 * i) + 1)) (Array.unsafe_get sp ((4 * i) + 2)) r2 o d nr.(4) in
    if replaces ctx (Array.unsafe_get g.bounded i) t nr.(0) r.best_id o d then begin
      nr.(0) <- t;
      r.best_id <- (Array.unsafe_get g.bounded i).id;
      r.best_face <- -1
    end
  end
  else begin
    let b = 6 * i in
    let x0 = Array.unsafe_get bx b in
    if x0 <> x0 then try_obj ctx g.bounded.(i) o d
    else begin
      (* a costly shape is tried only when the ray meets its own box before the limit, as
         it would meet the box of a leaf holding the shape alone *)
      let best = nr.(0) in
      let lim = if ctx.robust && r.best_id >= 0 then best +. tie_tolerance o best else best in
      let idx = nr.(1) and idy = nr.(2) and idz = nr.(3) in
      let tx0 = (x0 -. o.x) *. idx and tx1 = (Array.unsafe_get bx (b + 3) -. o.x) *. idx in
      let ty0 = (Array.unsafe_get bx (b + 1) -. o.y) *. idy and ty1 = (Array.unsafe_get bx (b + 4) -. o.y) *. idy in
      let tz0 = (Array.unsafe_get bx (b + 2) -. o.z) *. idz and tz1 = (Array.unsafe_get bx (b + 5) -. o.z) *. idz in
      let near = fmax (fmax (fmin tx0 tx1) (fmin ty0 ty1)) (fmax (fmin tz0 tz1) 0.) in
      let far = fmin (fmin (fmax tx0 tx1) (fmax ty0 ty1)) (fmin (fmax tz0 tz1) lim) in
      if near <= far then try_obj ctx g.bounded.(i) o d
    end
  end;
  (* the robust mode still looks for ties just beyond the best depth *)
  let l = if ctx.robust && r.best_id >= 0 then nr.(0) +. tie_tolerance o nr.(0) else nr.(0) in
  let wl = ctx.walk_lim in
  wl.(0) <- fmin wl.(0) l

(* The nearest object of [g] hit at a depth in [lo, hi): its id, or −1. Its depth is left in
   [ctx.depth.(0)] and, for a mesh, its face in [ctx.sub.(0)]. Of equal depths the one POV-Ray
   meets first wins ([wins_tie]); in the robust mode, of depths within rounding of each other the
   one written first. The best so far lives in [ctx.near] and [ctx.best], the ray in one small record. *)
let nearest ctx (g : group) (o : Vec.t) (d : Vec.t) lo hi =
  let nr = ctx.near and r = ctx.best in
  nr.(0) <- hi;
  nr.(4) <- lo;
  r.best_id <- -1;
  r.best_face <- -1;
  let un = g.unbounded in
  for k = 0 to Array.length un - 1 do try_obj ctx (Array.unsafe_get un k) o d done;
  nr.(1) <- recip d.x;
  nr.(2) <- recip d.y;
  nr.(3) <- recip d.z;
  if g.bvh.nodes > 0 then begin
    ctx.walk_lim.(0) <- hi;
    Bvh.walk_with g.bvh ctx.stack o.x o.y o.z d.x d.y d.z ctx.walk_lim visit_bounded { sctx = ctx; sgroup = g; so = o; sd = d }
  end;
  ctx.depth.(0) <- nr.(0);
  ctx.sub.(0) <- r.best_face;
  r.best_id

(* The surface at a hit: a mesh face may carry its own texture. *)
let surface_of obj sub =
  match obj.shape with
  | Mesh m when sub >= 0 ->
      let t = Mesh.texture m.mesh sub in
      if t >= 0 then obj.face_surfs.(t) else obj.surf
  | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _
  | Disc _ | Torus _ | Glyph _ | Csg _ ->
      obj.surf

(* Box::Normal: the outward axis of the side hit (1–6). *)
let box_side_normal side =
  match side with
  | 1 -> Vec.make (-1.) 0. 0.
  | 2 -> Vec.make 1. 0. 0.
  | 3 -> Vec.make 0. (-1.) 0.
  | 4 -> Vec.make 0. 1. 0.
  | 5 -> Vec.make 0. 0. (-1.)
  | _ -> Vec.make 0. 0. 1.

(* Cone::Normal (§15.2, §15.3): in canonical space the side's (x, y, 0) for a cylinder and
   (x, y, −z) for a cone, the ends ±z; then by the inverse transpose, normalised (§14.6). *)
let cone_normal (c : cone) part (p : Vec.t) =
  let n =
    if part = cap_hit then Vec.make 0. 0. 1.
    else if part = base_hit then Vec.make 0. 0. (-1.)
    else
      let q = Transform.inv_point c.ctr p in
      if c.cyl then Vec.make q.x q.y 0. else Vec.make q.x q.y (-.q.z)
  in
  Transform.normalize (Transform.normal c.ctr n)

let normal obj sub (p : Vec.t) : Vec.t =
  match obj.shape with
  | Cone c -> cone_normal c sub p
  | Disc dc -> Vec.make dc.dnx dc.dny dc.dnz
  | Csg _ -> Vec.make 0. 0. 1. (* never hit: the member primitive is *)
  | Box _ -> box_side_normal sub
  | Box_trans { btr; _ } -> Transform.normalize (Transform.normal btr (box_side_normal sub))
  | Torus t -> Torus.normal t p
  | Glyph g -> Glyph.normal g sub
  | Sphere s -> Vec.make ((p.x -. s.cx) /. s.radius) ((p.y -. s.cy) /. s.radius) ((p.z -. s.cz) /. s.radius)
  | Ellipsoid { sp = s; etr } ->
      (* Sphere::Normal: P' − C in object space, by the inverse transpose, normalised (§14.6) *)
      let q = Transform.inv_point etr p in
      Transform.normalize (Transform.normal etr (Vec.make (q.x -. s.cx) (q.y -. s.cy) (q.z -. s.cz)))
  | Plane pl -> Vec.make pl.nx pl.ny pl.nz
  | Plane_trans { pnormal; _ } -> pnormal
  | Triangle t -> Vec.make t.nx t.ny t.nz
  | Smooth_triangle t -> Triangle.smooth_normal t p
  | Mesh m ->
      (* Mesh::Normal: with a transform, the unnormalised mesh-space normal by the inverse
         transpose, normalised once (§2.6, §14.6) *)
      if m.moved then Transform.normalize (Transform.normal m.tr (Mesh.raw_normal m.mesh sub (Transform.inv_point m.tr p)))
      else Mesh.normal m.mesh sub p

(* ---------------------------------------------------------------------------------------------- *)
(* The robust mode's secondary-ray origins. A computed hit point is off the true surface by a few
   rounding errors of the coordinates it was computed from; a secondary ray leaves from the point
   moved off the surface, to the side the ray goes, by a bound on that error, and then accepts every
   positive depth. Every length here is relative to the coordinates, so the decision is the same
   whatever the size and position of the scene. *)

(* The flat normal of the surface at [p] (for a smooth triangle or face: the face's own). *)
let geometric_normal obj sub (p : Vec.t) =
  match obj.shape with
  | Smooth_triangle t -> Vec.make t.nx t.ny t.nz
  | Mesh m -> if m.moved then Transform.normalize (Transform.normal m.tr (Mesh.face_normal m.mesh sub)) else Mesh.face_normal m.mesh sub
  | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ | Csg _ -> normal obj sub p

(* A hit point put back onto a sphere: o + t·d is off by rounding errors of the size of the ray's
   length, a point projected from the centre by those of the centre and radius only. *)
let refine obj (p : Vec.t) =
  let onto cx cy cz r (q : Vec.t) =
    let dx = q.x -. cx and dy = q.y -. cy and dz = q.z -. cz in
    let len = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
    if len = 0. then q else let k = Float.abs r /. len in Vec.make (cx +. (k *. dx)) (cy +. (k *. dy)) (cz +. (k *. dz))
  in
  match obj.shape with
  | Sphere s -> onto s.cx s.cy s.cz s.radius p
  | Ellipsoid { sp = s; etr } -> Transform.point etr (onto s.cx s.cy s.cz s.radius (Transform.inv_point etr p))
  | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ | Csg _ -> p

let norm_inf (v : Vec.t) = Float.max (Float.abs v.x) (Float.max (Float.abs v.y) (Float.abs v.z))

(* A bound on the error of the hit point [p] of a ray from [o] on a shape whose coordinates reach
   [mag]: 256 units in the last place of the largest coordinate involved. *)
let error_bound (o : Vec.t) (p : Vec.t) mag = 0x1p-44 *. (norm_inf o +. norm_inf p +. mag)

(* Where a ray in direction [dir] leaves the surface at [p]: [p] itself in POV-Ray's mode; in the
   robust mode, [p] moved by [e] along the geometric normal [ng] to the side [dir] goes. *)
let[@inline] origin ctx (p : Vec.t) (ng : Vec.t) e (dir : Vec.t) =
  if not ctx.robust then p else if Vec.dot dir ng >= 0. then Vec.madd p e ng else Vec.madd p (-.e) ng

(* ---------------------------------------------------------------------------------------------- *)
(* Shadows (§4) *)

let[@inline] fade_factor fade_colour fade_distance fade_power depth (c : Rgb.t) =
  (* §4 and §6.3: exponential above fade_power 1000, else fade_colour + (1 − fade_colour)/(1 + (d/fd)^fp) *)
  if fade_power >= 1000. then
    let k x = f32 (exp (-.f32 (1. -. x) *. (depth /. fade_distance))) in
    Rgb.make (f32 (c.r *. k fade_colour.Rgb.r)) (f32 (c.g *. k fade_colour.g)) (f32 (c.b *. k fade_colour.b))
  else
    let a = 1. +. Float.pow (depth /. fade_distance) fade_power in
    let k x = f32 (x +. f32 (f32 (1. -. x) /. a)) in
    Rgb.make (f32 (c.r *. k fade_colour.Rgb.r)) (f32 (c.g *. k fade_colour.g)) (f32 (c.b *. k fade_colour.b))

let rec remove id = function [] -> [] | x :: rest -> if x = id then rest else x :: remove id rest

(* The light colour [lc] after the shadow ray from [p] (on a surface with geometric normal [ng] and
   error bound [e], for the robust mode) towards the light at [dist]; [slot] is the light's
   shadow-cache slot.
   §4, TracePointLightShadowRay: the opaque object that last blocked this light (in this worker, at
   this kind of level) is tested first, for a hit from MIN_ISECT_DEPTH (1e-4) to the light itself,
   not from 1e-3 to the light minus 1e-3; a hit there is a full shadow. Otherwise the nearest
   blocker is searched for as usual, and if the first surface met is opaque it becomes the cached
   object. The cache is what makes a blocker closer than 1e-3 (but beyond 1e-4) shadow a point
   right after a neighbouring point was shadowed by it.
   The robust mode counts every hit from the lifted origin to the light minus a relative margin,
   the cached object's too. *)
(* The robust mode's shadow segment from [o] to the light at [lp]: its direction and length. *)
let aim (lp : Vec.t) (o : Vec.t) =
  let v = Vec.sub lp o in
  let len = Vec.length v in
  (Vec.scale (1. /. len) v, len)

(* How far short of the light at [lp] a robust shadow segment of length [remaining] from near [p]
   stops counting hits. *)
let robust_margin (p : Vec.t) (lp : Vec.t) remaining = (1e-9 *. remaining) +. error_bound p lp remaining

(* The walk of a shadow ray from [o] along [l] towards the light at [lp], [remaining] from it,
   through non-opaque occluders ([shadow] below); [first] on the first segment, whose opaque
   blocker is cached. *)
let rec shadow_walk ctx ~slot (p : Vec.t) (lp : Vec.t) lo first (o : Vec.t) (l : Vec.t) remaining interiors (lc : Rgb.t) =
  let sc = ctx.scene in
  let i = nearest ctx sc.occluders o l lo remaining in
  let t = ctx.depth.(0) in
  if i < 0 || t >= remaining -. (if ctx.robust then robust_margin p lp remaining else shadow_tolerance) then lc
  else
    let obj = sc.objects.(i) in
    if obj.opaque then begin
      (* the cache holds the top-level object (a CSG, not its member), and a CSG only when
         its own texture is opaque: POV-Ray tests the OPAQUE flag of Intersection.Csg *)
      if first && not sc.objects.(obj.top).surf.transparent then ctx.shadow_cache.(slot) <- obj.top;
      Rgb.black
    end
    else
      let sf = surface_of obj ctx.sub.(0) in
      (* §4, §17.8: a patterned pigment is evaluated where the shadow ray crosses it *)
      let f = match sf.paint with Fixed -> sf.filcol | Varying at -> (at (Vec.madd o t l)).filcol in
      let f =
        if List.mem obj.iid interiors && obj.fade_power > 0. && Float.abs obj.fade_distance > epsilon then
          fade_factor obj.fade_colour obj.fade_distance obj.fade_power t f
        else f
      in
      let lc = Rgb.make (f32 (lc.r *. f.r)) (f32 (lc.g *. f.g)) (f32 (lc.b *. f.b)) in
      let interiors = if List.mem obj.iid interiors then remove obj.iid interiors else obj.iid :: interiors in
      let q = Vec.madd o t l in
      if not ctx.robust then shadow_walk ctx ~slot p lp lo false q l (remaining -. t) interiors lc
      else
        let sub = ctx.sub.(0) in
        let q = refine obj q in
        let next = origin ctx q (geometric_normal obj sub q) (error_bound o q obj.mag) l in
        let l, remaining = aim lp next in
        shadow_walk ctx ~slot p lp lo false next l remaining interiors lc

let shadow ctx ~slot (p : Vec.t) (ng : Vec.t) e (l : Vec.t) dist interiors (lc : Rgb.t) : Rgb.t =
  let sc = ctx.scene in
  ctx.stats.shadow_rays <- ctx.stats.shadow_rays + 1;
  (* a light at an infinite distance (a coordinate beyond the float range) has no direction: a
     filtered walk towards it would never end (a NaN ray from inside a box's slabs meets the box
     at 2e10 again and again) *)
  if not (Float.is_finite dist) then lc
  else
  match sc.shadow_mode with
  | No_occluders -> lc
  | Any_hit | Filtered ->
      (* POV-Ray: hits from 1e-3 to the light minus 1e-3, the ray going on from each crossing. The
         robust mode: every segment starts at a lifted origin and is aimed at the light anew, so
         the lift never shortens the way to the light; hits count up to the light minus a margin
         relative to the segment's length. *)
      let lp = if ctx.robust then Vec.madd p dist l else p in
      let lo = if ctx.robust then 0. else shadow_tolerance in
      let o = origin ctx p ng e l in
      let l, dist = if ctx.robust then aim lp o else (l, dist) in
      let cached = ctx.shadow_cache.(slot) in
      let in_cache =
        cached >= 0
        &&
        (if ctx.robust then hit_shape ctx sc.objects.(cached).shape o l lo < dist -. robust_margin p lp dist
         else hit_shape ctx sc.objects.(cached).shape p l min_isect_depth < dist)
        &&
        (* a cached CSG shadows only if the member hit is opaque *)
        match sc.objects.(cached).shape with
        | Csg _ -> sc.objects.(ctx.leaf.(0)).opaque
        | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ -> true
      in
      if in_cache then Rgb.black
      else
      shadow_walk ctx ~slot p lp lo true o l dist interiors lc

(* ---------------------------------------------------------------------------------------------- *)
(* Local illumination (§3.3, §3.4) *)

(* §3.3: the empirical metallic Fresnel term for highlights and metallic reflection. *)
let metallic_factor metallic cos_angle (c : Rgb.t) (lc : Rgb.t) =
  let x = Float.abs (acos cos_angle) /. (Float.pi /. 2.) in
  let f = (0.014567225 /. ((x -. 1.12) *. (x -. 1.12))) -. 0.011612903 in
  let f = Float.min 1. (Float.max 0. f) in
  let m = metallic *. (1. -. f) in
  let k ch = f32 (1. +. f32 (m *. f32 (ch -. 1.))) in
  Rgb.make (f32 (lc.r *. k c.r)) (f32 (lc.g *. k c.g)) (f32 (lc.b *. k c.b))

(* §3.4, cubic_spline: 0 below [lo], 1 from [hi] on, the smooth step (3 − 2s)s² between. *)
let cubic_spline lo hi p = if p < lo then 0. else if p >= hi then 1. else let s = (p -. lo) /. (hi -. lo) in (3. -. (2. *. s)) *. s *. s

(* §3.4, §18.2, §18.3, Attenuate_Light: the factor of the light [lt] at [p], whose light ray has
   the unit direction [l] and length [dist] (for a parallel light, the depth in front of its plane). *)
let attenuation (lt : light) (p : Vec.t) (l : Vec.t) dist =
  let a =
    match lt.spread with
    | Everywhere -> 1.
    | Spot c ->
        (* the ray's cosine with the spot axis, turned round for a light in front of the point *)
        let ct = (l.x *. lt.dx) +. (l.y *. lt.dy) +. (l.z *. lt.dz) in
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

(* §18.3, ComputeOneWhiteLightRay: the length of a parallel light's ray from a point whose unit
   direction to the centre is [l] at distance [dist]: dist·(−dir·l), the signed distance of the
   point in front of the plane through the centre perpendicular to dir. *)
let parallel_depth (lt : light) (l : Vec.t) dist = dist *. -.((lt.dx *. l.x) +. (lt.dy *. l.y) +. (lt.dz *. l.z))

(* One light's diffuse, phong and specular terms, summed in single precision the way POV-Ray sums
   them: per light first, then into the surface colour. [di]: the object is double_illuminate. *)
let light_terms ctx ~slot ~di (s : surface) (p : Vec.t) (n : Vec.t) ng e (d : Vec.t) interiors (lt : light) : Rgb.t =
  let acc = Rgb.black in
  let lvx = lt.lx -. p.x and lvy = lt.ly -. p.y and lvz = lt.lz -. p.z in
  let dist = sqrt ((lvx *. lvx) +. (lvy *. lvy) +. (lvz *. lvz)) in
  (* ComputeOneWhiteLightRay: VInverseScaleEq, times the reciprocal of the distance; the last bit
     decides knife-edge shadow rays, such as one through faces shared by CSG members *)
  let k = 1. /. dist in
  let l = Vec.make (lvx *. k) (lvy *. k) (lvz *. k) in
  (* §18.3: a parallel light's ray runs along −dir, as far as the plane through the centre *)
  let dist = if lt.parallel then parallel_depth lt l dist else dist in
  let l = if lt.parallel then Vec.make (-.lt.dx) (-.lt.dy) (-.lt.dz) else l in
  let a = attenuation lt p l dist in
  let lc =
    if a <> 1. then Rgb.make (f32 (lt.lcolour.r *. a)) (f32 (lt.lcolour.g *. a)) (f32 (lt.lcolour.b *. a)) else lt.lcolour
  in
  let small (c : Rgb.t) bound = Float.abs c.r < bound && Float.abs c.g < bound && Float.abs c.b < bound in
  if small lc epsilon then Rgb.black
  else
    let nl = Vec.dot n l in
    (* §16.6: double_illuminate skips the test of the side the light is on *)
    if (not di) && nl < epsilon then Rgb.black
    else
      (* a point behind a parallel light's plane is never shadowed (§18.3) *)
      let lc = if lt.shadowless || dist <= 0. then lc else shadow ctx ~slot p ng e l dist interiors lc in
      if Float.abs lc.r <= epsilon && Float.abs lc.g <= epsilon && Float.abs lc.b <= epsilon then Rgb.black
      else
        let acc =
          if s.diffuse > 0. then
            let anl = Float.abs nl in
            let i = (if s.brilliance = 1. then anl else Float.pow anl s.brilliance) *. (s.diffuse *. s.att) in
            Rgb.make
              (f32 (acc.r +. f32 (f32 (s.colour.r *. i) *. lc.r)))
              (f32 (acc.g +. f32 (f32 (s.colour.g *. i) *. lc.g)))
              (f32 (acc.b +. f32 (f32 (s.colour.b *. i) *. lc.b)))
          else acc
        in
        if lt.shadowless then acc (* §3.3: fill lights give no highlights *)
        else
          let hl = if s.metallic <> 0. then metallic_factor s.metallic nl s.colour lc else lc in
          let acc =
            if s.phong > 0. then
              let dn = Vec.dot d n in
              let r = Vec.madd d (-2. *. dn) n in
              let c = Vec.dot r l in
              if c > 0. && (s.phong_size < 60. || c > 0.0008) then
                let i = s.phong *. Float.pow c s.phong_size in
                Rgb.make (f32 (acc.r +. f32 (i *. hl.r))) (f32 (acc.g +. f32 (i *. hl.g))) (f32 (acc.b +. f32 (i *. hl.b)))
              else acc
            else acc
          in
          if s.specular > 0. then
            let h = Vec.scale 0.5 (Vec.sub l d) in
            let hlen = Vec.length h in
            if hlen > 0. then
              let c = Vec.dot h n /. hlen in
              if c > 0. then
                let i = s.specular *. Float.pow c s.spec_exp in
                Rgb.make (f32 (acc.r +. f32 (i *. hl.r))) (f32 (acc.g +. f32 (i *. hl.g))) (f32 (acc.b +. f32 (i *. hl.b)))
              else acc
            else acc
          else acc

let add_lights ctx ~level ~di s p n ng e d interiors (acc : Rgb.t) =
  let lights = ctx.scene.lights in
  let acc = ref acc in
  for k = 0 to Array.length lights - 1 do
    let slot = (2 * k) + if level = 2 then 0 else 1 in
    let t = light_terms ctx ~slot ~di s p n ng e d interiors lights.(k) in
    let a = !acc in
    acc := Rgb.make (f32 (a.r +. t.r)) (f32 (a.g +. t.g)) (f32 (a.b +. t.b))
  done;
  !acc

(* ---------------------------------------------------------------------------------------------- *)
(* Reflectivity (§5.2) *)

(* §5.2: the ratio n_transmitted / n_incident seen by the Fresnel term. *)
let fresnel_ior sc obj interiors =
  match interiors with
  | [] -> obj.ior
  | last :: rest ->
      if List.mem obj.iid interiors then if rest = [] then 1. /. obj.ior else sc.objects.(last).ior /. obj.ior
      else obj.ior /. sc.objects.(last).ior

(* k·hi + (1 − k)·lo in single precision *)
let blend k (hi : Rgb.t) (lo : Rgb.t) =
  let k' = 1. -. k in
  Rgb.make (f32 (f32 (hi.r *. k) +. f32 (lo.r *. k'))) (f32 (f32 (hi.g *. k) +. f32 (lo.g *. k'))) (f32 (f32 (hi.b *. k) +. f32 (lo.b *. k')))

let reflectivity sc (s : surface) obj interiors ci : Rgb.t =
  let r = s.refl in
  if not r.fresnel then
    let frac = if Float.abs (r.falloff -. 1.) > epsilon then Float.pow (1. -. ci) r.falloff else 1. -. ci in
    if Float.abs frac < epsilon then r.rmin
    else if Float.abs (frac -. 1.) < epsilon then r.rmax
    else blend frac r.rmax r.rmin
  else
    let n = fresnel_ior sc obj interiors in
    let sq = (n *. n) +. (ci *. ci) -. 1. in
    if sq > 0. then
      let g = sqrt sq in
      let a = (g -. ci) /. (g +. ci) in
      let b = ((ci *. (g +. ci)) -. 1.) /. ((ci *. (g -. ci)) +. 1.) in
      let f = 0.5 *. a *. a *. (1. +. (b *. b)) in
      let f = Float.min 1. (Float.max 0. f) in
      blend f r.rmax r.rmin
    else r.rmax

(* ---------------------------------------------------------------------------------------------- *)
(* Sky and background (§8.4, §18.1) *)

let sky_colour sc (d : Vec.t) : result =
  let bg = sc.background in
  match sc.sky with
  | None -> if sc.legacy then { r = bg.red; g = bg.green; b = bg.blue; tr = bg.transmit } else { r = bg.red; g = bg.green; b = bg.blue; tr = 0. }
  | Some sky ->
      (* §18.1: the pigments are evaluated at the ray direction taken as a point, brought back
         through the sky's own transform *)
      let p = match sky.sky_trans with None -> d | Some t -> Transform.inv_point t d in
      let pigs = List.rev_map (fun pg -> Pigment.colour_at pg p) sky.sky_pigments in
      let e = sky.sky_emission in
      if not sc.legacy then
        let col, fil =
          List.fold_left
            (fun ((col : Rgb.t), (fil : Rgb.t)) (c : Colour.t) ->
              let k = 1. -. c.filter -. c.transmit in
              ( Rgb.add col (Rgb.mul (Rgb.scale k (Rgb.mul (Colour.rgb c) fil)) e),
                Rgb.mul fil (Colour.transmitted c) ))
            (Rgb.black, Rgb.white) pigs
        in
        let col = Rgb.add col (Rgb.mul (Colour.rgb bg) fil) in
        { r = col.r; g = col.g; b = col.b; tr = 0. }
      else
        let col, f, _ =
          List.fold_left
            (fun ((col : Rgb.t), (f : Colour.t), tr) (c : Colour.t) ->
              let col = Rgb.add col (Rgb.scale (tr *. (1. -. c.filter -. c.transmit)) (Colour.rgb c)) in
              let f =
                { Colour.red = f.red *. c.red; green = f.green *. c.green; blue = f.blue *. c.blue; filter = f.filter *. c.filter; transmit = f.transmit *. c.transmit }
              in
              (col, f, Float.abs f.filter +. Float.abs f.transmit))
            (Rgb.black, { Colour.red = 1.; green = 1.; blue = 1.; filter = 1.; transmit = 1. }, 1.)
            pigs
        in
        let col = Rgb.add (Rgb.mul col e) (Rgb.mul (Colour.rgb bg) (Colour.transmitted f)) in
        { r = col.r; g = col.g; b = col.b; tr = 0. }

(* ---------------------------------------------------------------------------------------------- *)
(* The recursive trace (§7) and surface colour (§6.5) *)

(* §16.6: a ray is a reflection ray ([reflected]) when it or an ancestor was reflected, else an image
   ray; each kind searches the objects it can meet. *)
let rec trace_ray ctx ~reflected ~level ~weight ~interiors ~continued (o : Vec.t) (d : Vec.t) : result =
  let sc = ctx.scene in
  if level >= sc.max_trace_level || weight < sc.adc_bailout then black
  else
    let i = nearest ctx (if reflected then sc.mirrored else sc.seen) o d ctx.min_depth infinity in
    if i < 0 then sky_colour sc d
    else
      let level = if continued then level else level + 1 in
      if level > ctx.stats.max_level then ctx.stats.max_level <- level;
      shade ctx ~reflected sc.objects.(i) ctx.sub.(0) ctx.depth.(0) ~level ~weight ~interiors o d

and shade ctx ~reflected obj sub depth ~level ~weight ~interiors (o : Vec.t) (d : Vec.t) : result =
  let sc = ctx.scene in
  (* §3.2: the layer loop runs while the remaining translucency (1 at the start) exceeds adc_bailout *)
  if not (1. > sc.adc_bailout) then black
  else
    let p = Vec.madd o depth d in
    let p = if ctx.robust then refine obj p else p in
    let s = surface_of obj sub in
    (* §17.1: a pattern pigment is evaluated at the hit point *)
    let s = match s.paint with Fixed -> s | Varying at -> at p in
    let n = normal obj sub p in
    let n = if Vec.dot n d > 0. then Vec.neg n else n in
    (* §3.1 *)
    (* where secondary rays leave from in the robust mode *)
    let ng = if ctx.robust then geometric_normal obj sub p else n in
    let e = if ctx.robust then error_bound o p obj.mag else 0. in
    let ci = -.Vec.dot d n in
    let refl = if s.reflects then reflectivity sc s obj interiors ci else Rgb.black in
    (* §5.2: the reflected ray's weight, taken before the metallic tint *)
    let w_refl =
      f32 (if s.refl.fresnel then weight *. Rgb.max3 refl else weight *. Float.max (Rgb.max3 s.refl.rmax) (Rgb.max3 s.refl.rmin))
    in
    let refl = if s.reflects && s.refl.refl_metallic <> 0. then metallic_factor s.refl.refl_metallic ci s.colour refl else refl in
    let local = if s.lit then add_lights ctx ~level ~di:obj.double_illuminate s p n ng e d interiors s.emitted else s.emitted in
    (* §6: transmitted ray *)
    let local, tr, tir =
      if not s.transparent then (local, 0., false)
      else
        let filcol =
          if s.conserve && s.reflects then
            let k x = f32 (Float.min 1. (1. -. x)) in
            Rgb.make (f32 (s.filcol.r *. k refl.r)) (f32 (s.filcol.g *. k refl.g)) (f32 (s.filcol.b *. k refl.b))
          else s.filcol
        in
        let trans = Float.min 1. (Float.abs (Rgb.intensity filcol)) in
        if not (trans > sc.adc_bailout) then (local, 0., false)
        else
          let w = f32 (weight *. Float.max (Float.abs filcol.r) (Float.max (Float.abs filcol.g) (Float.abs filcol.b))) in
          let ct, tir = refract ctx ~reflected obj ~level ~weight:w ~interiors p ng e d n in
          let att = Rgb.grey obj.old_refract in
          let att =
            if Float.abs obj.fade_distance > epsilon && List.mem obj.iid interiors then
              fade_factor obj.fade_colour obj.fade_distance obj.fade_power depth att
            else att
          in
          if tir then
            (Rgb.make (f32 (local.r +. f32 (att.r *. ct.r))) (f32 (local.g +. f32 (att.g *. ct.g))) (f32 (local.b +. f32 (att.b *. ct.b))), 0., true)
          else
            ( Rgb.make
                (f32 (local.r +. f32 (f32 (att.r *. ct.r) *. filcol.r)))
                (f32 (local.g +. f32 (f32 (att.g *. ct.g) *. filcol.g)))
                (f32 (local.b +. f32 (f32 (att.b *. ct.b) *. filcol.b))),
              f32 (Rgb.intensity att *. ct.tr *. trans),
              false )
    in
    (* §5.3: reflected ray, skipped after total internal reflection *)
    if tir || Rgb.is_zero refl then { r = local.r; g = local.g; b = local.b; tr }
    else
      let rd = Vec.normalize (Vec.madd d (-2. *. Vec.dot d n) n) in
      ctx.stats.reflected_rays <- ctx.stats.reflected_rays + 1;
      let c = trace_ray ctx ~reflected:true ~level ~weight:w_refl ~interiors ~continued:false (origin ctx p ng e rd) rd in
      let e = s.refl.exponent in
      if e <> 1. then
        let ie = 1. /. e in
        let ie = f32 ie in
        { r = f32 (local.r +. (refl.r *. Float.pow c.r ie)); g = f32 (local.g +. (refl.g *. Float.pow c.g ie)); b = f32 (local.b +. (refl.b *. Float.pow c.b ie)); tr }
      else { r = f32 (local.r +. f32 (refl.r *. c.r)); g = f32 (local.g +. f32 (refl.g *. c.g)); b = f32 (local.b +. f32 (refl.b *. c.b)); tr }

(* §6.2: the transmitted ray; returns its colour and whether total internal reflection happened. *)
and refract ctx ~reflected obj ~level ~weight ~interiors p ng e d n : result * bool =
  let sc = ctx.scene in
  let ior, inner =
    match interiors with
    | [] -> (1. /. obj.ior, [ obj.iid ])
    | last :: rest when last = obj.iid -> (obj.ior /. (match rest with [] -> 1. | l :: _ -> sc.objects.(l).ior), rest)
    | _ when List.mem obj.iid interiors -> (1., remove obj.iid interiors)
    | last :: _ -> (sc.objects.(last).ior /. obj.ior, obj.iid :: interiors)
  in
  ctx.stats.refracted_rays <- ctx.stats.refracted_rays + 1;
  if Float.abs (ior -. 1.) < epsilon then
    (* a continued ray: same direction, no new trace level *)
    (trace_ray ctx ~reflected ~level ~weight ~interiors:inner ~continued:true (origin ctx p ng e d) d, false)
  else
    let dn = Vec.dot d n in
    let nn, nl = if dn <= 0. then (-.dn, n) else (dn, Vec.neg n) in
    let t = 1. +. (ior *. ior *. ((nn *. nn) -. 1.)) in
    if t < 0. then
      let rd = Vec.normalize (Vec.madd d (-2. *. dn) n) in
      (* total internal reflection: a reflected ray (§16.6) *)
      (trace_ray ctx ~reflected:true ~level ~weight ~interiors ~continued:false (origin ctx p ng e rd) rd, true)
    else
      let dir = Vec.add (Vec.scale ior d) (Vec.scale ((ior *. nn) -. sqrt t) nl) in
      (trace_ray ctx ~reflected ~level ~weight ~interiors:inner ~continued:false (origin ctx p ng e dir) dir, false)

let trace ctx ~level ~weight ~interiors ~continued o d = trace_ray ctx ~reflected:false ~level ~weight ~interiors ~continued o d
