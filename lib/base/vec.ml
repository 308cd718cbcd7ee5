(* Vectors of three doubles, an all-float record stored unboxed; small operations inlined. *)

type t = { x : float; y : float; z : float }

let[@inline] make x y z = { x; y; z }
let zero = { x = 0.; y = 0.; z = 0. }
let[@inline] add a b = { x = a.x +. b.x; y = a.y +. b.y; z = a.z +. b.z }
let[@inline] sub a b = { x = a.x -. b.x; y = a.y -. b.y; z = a.z -. b.z }
let[@inline] neg a = { x = -.a.x; y = -.a.y; z = -.a.z }
let[@inline] scale s a = { x = s *. a.x; y = s *. a.y; z = s *. a.z }
let[@inline] mul a b = { x = a.x *. b.x; y = a.y *. b.y; z = a.z *. b.z }
let[@inline] dot a b = (a.x *. b.x) +. (a.y *. b.y) +. (a.z *. b.z)

let[@inline] cross a b =
  {
    x = (a.y *. b.z) -. (a.z *. b.y);
    y = (a.z *. b.x) -. (a.x *. b.z);
    z = (a.x *. b.y) -. (a.y *. b.x);
  }

let[@inline] length2 a = dot a a
let[@inline] length a = sqrt (dot a a)

(* VNormalize: times the reciprocal of the length, as POV-Ray does (not a division, which can
   differ in the last bit) *)
let[@inline] normalize a =
  let l = length a in
  if l = 0. then a
  else
    let k = 1. /. l in
    { x = a.x *. k; y = a.y *. k; z = a.z *. k }

let[@inline] madd a s b = { x = a.x +. (s *. b.x); y = a.y +. (s *. b.y); z = a.z +. (s *. b.z) }
let to_string a = Printf.sprintf "<%g, %g, %g>" a.x a.y a.z
