(* Jitter (§9.2): deterministic offsets in [-0.5, 0.5]. *)

let positions =
  List.concat_map
    (fun i -> List.map (fun j -> ((float_of_int i *. 0.37) -. 3., (float_of_int j *. 0.71) -. 2.)) (List.init 40 Fun.id))
    (List.init 40 Fun.id)

let test_range () =
  List.iter
    (fun (x, y) ->
      let a = Jitter.jx x y and b = Jitter.jy x y in
      if not (a >= -0.5 && a <= 0.5 && b >= -0.5 && b <= 0.5) then Alcotest.failf "jitter out of range at (%g, %g): %g %g" x y a b)
    positions

let test_deterministic () =
  List.iter
    (fun (x, y) ->
      Alcotest.(check (float 0.)) "jx twice" (Jitter.jx x y) (Jitter.jx x y);
      Alcotest.(check (float 0.)) "jy twice" (Jitter.jy x y) (Jitter.jy x y))
    positions

let test_varies () =
  (* the offsets are not constant, and jx and jy are different functions *)
  let xs = List.sort_uniq compare (List.map (fun (x, y) -> Jitter.jx x y) positions) in
  Alcotest.(check bool) "many distinct jx values" true (List.length xs > 50);
  Alcotest.(check bool) "jx ≠ jy somewhere" true (List.exists (fun (x, y) -> Jitter.jx x y <> Jitter.jy x y) positions);
  (* the table holds single-precision values: each offset is exactly representable as a float32 *)
  List.iter
    (fun (x, y) ->
      let a = Jitter.jx x y in
      Alcotest.(check (float 0.)) "single precision" (Precision.f32 a) a)
    positions

let tests =
  [
    Alcotest.test_case "range" `Quick test_range;
    Alcotest.test_case "deterministic" `Quick test_deterministic;
    Alcotest.test_case "varies" `Quick test_varies;
  ]
