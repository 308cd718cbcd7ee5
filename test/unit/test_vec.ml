(* Vec: vector algebra, every value computed by hand. *)

open Helpers

let a = v 1. 2. 3.
let b = v 4. 5. 6.

let test_add () = vec_eq "<1,2,3>+<4,5,6> = <5,7,9>" (v 5. 7. 9.) (Vec.add a b)
let test_sub () = vec_eq "<4,5,6>-<1,2,3> = <3,3,3>" (v 3. 3. 3.) (Vec.sub b a)
let test_neg () = vec_eq "-<1,2,3>" (v (-1.) (-2.) (-3.)) (Vec.neg a)
let test_scale () = vec_eq "2·<1,2,3> = <2,4,6>" (v 2. 4. 6.) (Vec.scale 2. a)
let test_mul () = vec_eq "<1,2,3>*<4,5,6> = <4,10,18>" (v 4. 10. 18.) (Vec.mul a b)

(* 1·4 + 2·5 + 3·6 = 4 + 10 + 18 = 32 *)
let test_dot () = float_eq "<1,2,3>·<4,5,6> = 32" 32. (Vec.dot a b)

let test_cross () =
  (* x × y = z in the formula a×b = (ay bz − az by, az bx − ax bz, ax by − ay bx) *)
  vec_eq "x×y = z" (v 0. 0. 1.) (Vec.cross (v 1. 0. 0.) (v 0. 1. 0.));
  vec_eq "y×x = -z" (v 0. 0. (-1.)) (Vec.cross (v 0. 1. 0.) (v 1. 0. 0.));
  (* <1,2,3>×<4,5,6> = (2·6−3·5, 3·4−1·6, 1·5−2·4) = (−3, 6, −3) *)
  vec_eq "<1,2,3>×<4,5,6> = <-3,6,-3>" (v (-3.) 6. (-3.)) (Vec.cross a b)

let test_length () =
  (* 3² + 4² + 12² = 9 + 16 + 144 = 169 = 13² *)
  float_eq "|<3,4,12>| = 13" 13. (Vec.length (v 3. 4. 12.));
  float_eq "|<3,4,12>|² = 169" 169. (Vec.length2 (v 3. 4. 12.));
  float_eq "|0| = 0" 0. (Vec.length Vec.zero)

let test_normalize () =
  (* |<0,3,4>| = 5, so <0, 0.6, 0.8> *)
  vec_eq "normalize <0,3,4>" (v 0. 0.6 0.8) (Vec.normalize (v 0. 3. 4.));
  vec_eq "normalize <0,0,-7>" (v 0. 0. (-1.)) (Vec.normalize (v 0. 0. (-7.)));
  let z = Vec.normalize Vec.zero in
  vec_eq "zero vector unchanged" Vec.zero z;
  Alcotest.(check bool) "no NaN from the zero vector" false (Float.is_nan z.x || Float.is_nan z.y || Float.is_nan z.z);
  (* VNormalize multiplies by the reciprocal of the length; a division can differ in the last bit:
     for <0.3,0.2,1.1>, 0.2/l = 0.17277368511627203 but 0.2·(1/l) = 0.172773685116272 *)
  let w = v 0.3 0.2 1.1 in
  let l = Vec.length w in
  Alcotest.(check bool) "the two roundings differ here" true (0.2 /. l <> 0.2 *. (1. /. l));
  float_eq ~eps:0. "times the reciprocal" (0.2 *. (1. /. l)) (Vec.normalize w).y

(* <1,1,1> + 2·<1,2,3> = <3,5,7> *)
let test_madd () = vec_eq "<1,1,1> + 2·<1,2,3>" (v 3. 5. 7.) (Vec.madd (v 1. 1. 1.) 2. a)

let test_make_zero () =
  vec_eq "make 1 2 3" a (Vec.make 1. 2. 3.);
  vec_eq "zero" (v 0. 0. 0.) Vec.zero

let test_to_string () = Alcotest.(check string) "to_string" "<1, 2.5, -3>" (Vec.to_string (v 1. 2.5 (-3.)))

let tests =
  [
    Alcotest.test_case "add" `Quick test_add;
    Alcotest.test_case "sub" `Quick test_sub;
    Alcotest.test_case "neg" `Quick test_neg;
    Alcotest.test_case "scale" `Quick test_scale;
    Alcotest.test_case "mul" `Quick test_mul;
    Alcotest.test_case "dot" `Quick test_dot;
    Alcotest.test_case "cross" `Quick test_cross;
    Alcotest.test_case "length" `Quick test_length;
    Alcotest.test_case "normalize" `Quick test_normalize;
    Alcotest.test_case "madd" `Quick test_madd;
    Alcotest.test_case "make and zero" `Quick test_make_zero;
    Alcotest.test_case "to_string" `Quick test_to_string;
  ]
