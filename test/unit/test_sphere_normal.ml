(* The sphere's normal (Sphere::Normal): P − C times the reciprocal of the radius
   (VInverseScaleEq), which for radius 0.9 differs from a division in the last bit. The last bit
   showed in aa_normal_refraction: a ray bouncing inside a bumpy glass sphere left it a few
   ulps off, and met a quilted box exactly on a cell boundary (x = 0.2, scale 0.2) on the other
   side of it. *)

let bits msg (e : float) (a : float) = Alcotest.(check int64) msg (Int64.bits_of_float e) (Int64.bits_of_float a)

let reciprocal () =
  let s = Sphere.make (Vec.make (-1.2) 0.9 0.) 0.9 in
  (* 0.0137/0.9 = 0.015222222222222222, 0.0137·(1/0.9) = 0.015222222222222224 *)
  let p = Vec.make (-1.2 +. 0.0137) (0.9 +. 0.0137) 0.0137 in
  let n = Sphere.normal s p in
  let k = 1. /. 0.9 in
  bits "x" ((p.x +. 1.2) *. k) n.x;
  bits "y" ((p.y -. 0.9) *. k) n.y;
  bits "z" 0.015222222222222224 n.z

let tests = [ Alcotest.test_case "normal: times 1/radius, not divided" `Quick reciprocal ]
