(* The disc: docs/povray-rules.md §15.4, §14.5 (b), POV-Ray's Disc. *)

type t = { dtr : Transform.t; dnx : float; dny : float; dnz : float; or2 : float; ir2 : float }

let epsilon = Precision.epsilon
let make ~(normal : Vec.t) ~radius ~hole dtr = { dtr; dnx = normal.x; dny = normal.y; dnz = normal.z; or2 = radius *. radius; ir2 = hole *. hole }

let crossings (w : Scratch.t) (dc : t) (o : Vec.t) (d : Vec.t) (out : float array) =
  let stats = w.stats in
  Stats.test stats Stats.disc;
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
        if depth > w.lim.near && depth < w.lim.far then begin
          Stats.hit stats Stats.disc;
          out.(0) <- depth;
          out.(1) <- 0.;
          1
        end
        else 0
      end
      else 0
    end
    else 0
  end
  else 0

let depth (w : Scratch.t) dc o d lo = Scratch.nearest_crossing w (crossings w dc o d w.crossings) lo

let hits (w : Scratch.t) dc id o d lo n =
  let k = crossings w dc o d w.crossings in
  if k > 0 then Scratch.push_ray w n lo w.crossings.(0) 0 id o d else n

let normal dc = Vec.make dc.dnx dc.dny dc.dnz
let inside dc p = (Transform.inv_point dc.dtr p).z < 0.0
let small_tolerance = 1e-3

let bounds dc =
  let r = sqrt dc.or2 in
  Transform.bounds dc.dtr [| -.r; -.r; -.small_tolerance; r; r; small_tolerance |]

let pov_box dc =
  let f32 = Precision.f32 and r = sqrt dc.or2 in
  Pov_box.mapped dc.dtr [| f32 (-.r); f32 (-.r); f32 (-.small_tolerance); f32 (2. *. r); f32 (2. *. r); f32 (2. *. small_tolerance) |]

let traits = { Traits.default with name = "disc" }
