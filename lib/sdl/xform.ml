(* Temporary: rotations for vrotate/vaxis_rotate until the Transform module lands. *)
type t = float array array

let rotate (r : Vec.t) : t =
  let rad d = d *. Float.pi /. 180. in
  let mx a = let c = cos a and s = sin a in [| [| 1.; 0.; 0. |]; [| 0.; c; s |]; [| 0.; -.s; c |] |] in
  let my a = let c = cos a and s = sin a in [| [| c; 0.; -.s |]; [| 0.; 1.; 0. |]; [| s; 0.; c |] |] in
  let mz a = let c = cos a and s = sin a in [| [| c; s; 0. |]; [| -.s; c; 0. |]; [| 0.; 0.; 1. |] |] in
  let mul a b = Array.init 3 (fun i -> Array.init 3 (fun j -> (a.(i).(0) *. b.(0).(j)) +. (a.(i).(1) *. b.(1).(j)) +. (a.(i).(2) *. b.(2).(j)))) in
  mul (mul (mx (rad r.x)) (my (rad r.y))) (mz (rad r.z))

let axis_rotate (v : Vec.t) deg : t =
  let v = Vec.normalize v in
  let a = deg *. Float.pi /. 180. in
  let c = cos a and s = sin a in
  [|
    [| (v.x *. v.x) +. (c *. (1. -. (v.x *. v.x))); (v.x *. v.y *. (1. -. c)) +. (v.z *. s); (v.x *. v.z *. (1. -. c)) -. (v.y *. s) |];
    [| (v.x *. v.y *. (1. -. c)) -. (v.z *. s); (v.y *. v.y) +. (c *. (1. -. (v.y *. v.y))); (v.y *. v.z *. (1. -. c)) +. (v.x *. s) |];
    [| (v.x *. v.z *. (1. -. c)) +. (v.y *. s); (v.y *. v.z *. (1. -. c)) -. (v.x *. s); (v.z *. v.z) +. (c *. (1. -. (v.z *. v.z))) |];
  |]

let point (m : t) (p : Vec.t) =
  Vec.make
    ((p.x *. m.(0).(0)) +. (p.y *. m.(1).(0)) +. (p.z *. m.(2).(0)))
    ((p.x *. m.(0).(1)) +. (p.y *. m.(1).(1)) +. (p.z *. m.(2).(1)))
    ((p.x *. m.(0).(2)) +. (p.y *. m.(1).(2)) +. (p.z *. m.(2).(2)))
