(* The box: docs/povray-rules.md §15.1, §14.5 (a), POV-Ray's Box. *)

type t = { x0 : float; y0 : float; z0 : float; x1 : float; y1 : float; z1 : float }
type moved = { bx : t; btr : Transform.t }

let epsilon = Precision.epsilon
let make (lo : Vec.t) (hi : Vec.t) = { x0 = lo.x; y0 = lo.y; z0 = lo.z; x1 = hi.x; y1 = hi.y; z1 = hi.z }

(* Box::Intersect: the slabs of the box [b] crossed by the ray from (px, py, pz) along
   (vx, vy, vz), not renormalised, so depths are world depths. The X slab uses exact comparisons;
   the Y and Z slabs keep the side already found when a crossing is within [w.lim.close] (1e-6) of
   it, unless the ray is steeper towards the new side. Sides are 1–6 (0: none yet). Whether the
   box is hit (the far crossing beyond the near limit); the crossings and their sides are left in
   [w.slab], [w.side_near] and [w.side_far]. The near crossing counts beyond the near limit, the
   far one always. Box::Intersect itself counts nothing: [slabs] counts a box test. *)
let crossed (w : Scratch.t) (b : t) px py pz vx vy vz =
  let box_close = w.lim.close in
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
  w.slab.t_near <- !tmin;
  w.slab.t_far <- !tmax;
  w.side_near <- !smin;
  w.side_far <- !smax;
  not (!miss || !tmax < w.lim.near)

let slabs (w : Scratch.t) b px py pz vx vy vz =
  Stats.test w.stats Stats.box;
  crossed w b px py pz vx vy vz

let depth_along (w : Scratch.t) b px py pz vx vy vz lo =
  if not (slabs w b px py pz vx vy vz) then infinity
  else
    let stats = w.stats and tmin = w.slab.t_near and tmax = w.slab.t_far in
    if tmin > w.lim.near && tmin >= lo && (tmin < tmax || tmax < lo) then begin
      (* both crossings are candidates, the far one pushed last; POV-Ray takes candidates from the
         top of its stack and keeps a strictly nearer one, so of two equal depths (a ray through an
         edge) the far crossing's side wins *)
      Stats.hit stats Stats.box;
      w.part <- w.side_near;
      tmin
    end
    else if tmax >= lo then begin
      Stats.hit stats Stats.box;
      w.part <- w.side_far;
      tmax
    end
    else infinity

let depth w b (o : Vec.t) (d : Vec.t) lo = depth_along w b o.x o.y o.z d.x d.y d.z lo

let moved_depth w { bx = b; btr = t } (o : Vec.t) (d : Vec.t) lo =
  let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
  let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
  let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  depth_along w b px py pz vx vy vz lo

(* Box::All_Intersections once the slabs are crossed: the near crossing beyond the near limit,
   then the far one. *)
let pair (w : Scratch.t) n lo id o d =
  let tmin = w.slab.t_near and tmax = w.slab.t_far in
  let smin = w.side_near and smax = w.side_far in
  Stats.hit w.stats Stats.box;
  let n = if tmin > w.lim.near then Scratch.push_ray w n lo tmin smin id o d else n in
  Scratch.push_ray w n lo tmax smax id o d

let hits w b id (o : Vec.t) (d : Vec.t) lo n = if slabs w b o.x o.y o.z d.x d.y d.z then pair w n lo id o d else n

let moved_hits w { bx; btr = t } id o d lo n =
  let q = Transform.inv_point t o and v = Transform.inv_direction t d in
  if slabs w bx q.x q.y q.z v.x v.y v.z then pair w n lo id o d else n

let side_normal side =
  match side with
  | 1 -> Vec.make (-1.) 0. 0.
  | 2 -> Vec.make 1. 0. 0.
  | 3 -> Vec.make 0. (-1.) 0.
  | 4 -> Vec.make 0. 1. 0.
  | 5 -> Vec.make 0. 0. (-1.)
  | _ -> Vec.make 0. 0. 1.

let moved_normal { btr; _ } side = Transform.normalize (Transform.normal btr (side_normal side))
let inside b (p : Vec.t) = not (p.x < b.x0 || p.x > b.x1 || p.y < b.y0 || p.y > b.y1 || p.z < b.z0 || p.z > b.z1)
let moved_inside { bx; btr } p = inside bx (Transform.inv_point btr p)
let bounds b = [| b.x0; b.y0; b.z0; b.x1; b.y1; b.z1 |]
let moved_bounds { bx = b; btr } = Transform.bounds btr [| b.x0; b.y0; b.z0; b.x1; b.y1; b.z1 |]
let pov_box b = Pov_box.of_min_max [| b.x0; b.y0; b.z0 |] [| b.x1; b.y1; b.z1 |]
let moved_pov_box { bx; btr } = Pov_box.mapped btr (pov_box bx)

let traits = { Traits.default with name = "box"; costly = false; box_test_free = true }
let moved_traits = { traits with costly = true }

(* Box::UVCoord: the object-space point made relative to the box (0 to 1 along each axis), then
   placed on the cross of a cube map: each side a quarter of the width and a third of the height,
   none mirrored when seen from outside *)
let uv_in b (p : Vec.t) side =
  let dx = b.x1 -. b.x0 and dy = b.y1 -. b.y0 and dz = b.z1 -. b.z0 in
  let px = (p.x -. b.x0) /. dx and py = (p.y -. b.y0) /. dy and pz = (p.z -. b.z0) /. dz in
  match side with
  | 1 -> Vec.make (pz /. 4.0) ((1.0 /. 3.0) +. (py /. 3.0)) 0.
  | 2 -> Vec.make ((3.0 /. 4.0) -. (pz /. 4.0)) ((1.0 /. 3.0) +. (py /. 3.0)) 0.
  | 3 -> Vec.make ((1.0 /. 4.0) +. (px /. 4.0)) (pz /. 3.0) 0.
  | 4 -> Vec.make ((1.0 /. 4.0) +. (px /. 4.0)) ((3.0 /. 3.0) -. (pz /. 3.0)) 0.
  | 5 -> Vec.make (1.0 -. (px /. 4.0)) ((1.0 /. 3.0) +. (py /. 3.0)) 0.
  | _ -> Vec.make ((1.0 /. 4.0) +. (px /. 4.0)) ((1.0 /. 3.0) +. (py /. 3.0)) 0.

let uv b side p = uv_in b p side
let moved_uv { bx; btr } side p = uv_in bx (Transform.inv_point btr p) side
