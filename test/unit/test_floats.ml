(* Floats: Float.min and Float.max in line, bit for bit the standard library's for every pair,
   signed zeros, infinities and NaNs of either sign included. *)

let specials = [ 0.; -0.; 1.; -1.; 0.5; -0.5; 1e-310; -1e-310; Float.max_float; infinity; neg_infinity; nan; -.nan ]
let bits = Int64.bits_of_float

let same name x y =
  let pair = Printf.sprintf "(%h, %h)" x y in
  Alcotest.(check int64) ("max " ^ name ^ pair) (bits (Float.max x y)) (bits (Floats.max x y));
  Alcotest.(check int64) ("min " ^ name ^ pair) (bits (Float.min x y)) (bits (Floats.min x y))

let test_specials () = List.iter (fun x -> List.iter (fun y -> same "" x y) specials) specials

let test_random () =
  let st = Random.State.make [| 35 |] in
  for _ = 1 to 10_000 do
    let x = Random.State.float st 2. -. 1. in
    let y = if Random.State.bool st then x else Random.State.float st 2. -. 1. in
    same "random " x y
  done

let test_max3 () =
  Alcotest.(check (float 0.)) "the largest channel" 0.75 (Floats.max3 (Rgb.make 0.25 0.75 (-1.)));
  Alcotest.(check int64) "+0 over −0" (bits 0.) (bits (Floats.max3 (Rgb.make (-0.) 0. (-0.))))

let tests =
  [
    Alcotest.test_case "min and max of special values" `Quick test_specials;
    Alcotest.test_case "min and max of random values" `Quick test_random;
    Alcotest.test_case "max3" `Quick test_max3;
  ]
