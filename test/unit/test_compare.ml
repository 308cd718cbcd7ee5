(* Compare: counts, peak, RMSE and PSNR of two encoded images. *)

let img w h f = { Encode.width = w; height = h; pixels = Bytes.init (3 * w * h) (fun i -> Char.chr (f i)) }

let get = function Ok c -> c | Error m -> Alcotest.failf "unexpected error: %s" m

let test_identical () =
  let a = img 2 2 (fun i -> i * 10) in
  let c = get (Compare.images a (img 2 2 (fun i -> i * 10))) in
  Alcotest.(check int) "pixels" 4 c.pixels;
  Alcotest.(check int) "differing" 0 c.differing;
  Alcotest.(check int) "peak" 0 c.peak;
  Alcotest.(check (float 0.)) "rmse" 0. c.rmse;
  Alcotest.(check (float 0.)) "share 1" 1. (Compare.identical_share c);
  Alcotest.(check bool) "psnr infinite" true (Compare.psnr c = infinity)

let test_one_pixel () =
  let a = img 2 2 (fun _ -> 100) in
  (* pixel 3 (bytes 9..11): green +10 *)
  let b = img 2 2 (fun i -> if i = 10 then 110 else 100) in
  let c = get (Compare.images a b) in
  Alcotest.(check int) "differing" 1 c.differing;
  Alcotest.(check int) "peak" 10 c.peak;
  (* rmse = sqrt(10²/12) = 2.8867513 *)
  Alcotest.(check (float 1e-7)) "rmse" 2.8867513 c.rmse;
  (* 3 of 4 pixels identical *)
  Alcotest.(check (float 1e-12)) "share" 0.75 (Compare.identical_share c);
  (* 20·log10(255/2.8867513) = 38.922616 dB *)
  Alcotest.(check (float 1e-5)) "psnr" 38.922616 (Compare.psnr c);
  (* the difference is symmetric, and two channels of one pixel count once *)
  let b2 = img 2 2 (fun i -> if i = 9 then 90 else if i = 11 then 103 else 100) in
  let c = get (Compare.images b2 a) in
  Alcotest.(check int) "one pixel, two channels" 1 c.differing;
  Alcotest.(check int) "peak of |−10| and 3" 10 c.peak

let test_sizes () =
  match Compare.images (img 2 2 (fun _ -> 0)) (img 2 1 (fun _ -> 0)) with
  | Ok _ -> Alcotest.fail "sizes differ: expected an error"
  | Error m -> Helpers.check_contains "message" ~sub:"2x2" m

let tests =
  [
    Alcotest.test_case "identical" `Quick test_identical;
    Alcotest.test_case "one pixel differs" `Quick test_one_pixel;
    Alcotest.test_case "sizes differ" `Quick test_sizes;
  ]
