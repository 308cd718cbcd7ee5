(* Encode (§8.1): working value → 8-bit file value. *)

let ch msg expected gamma x = Alcotest.(check int) msg expected (Encode.channel gamma x)

let test_gamma_off () =
  (* identity then floor(clip(x)·255 + 0.5) *)
  ch "0.5 → floor(127.5 + 0.5) = 128" 128 Scene.Gamma_off 0.5;
  ch "0.25 → floor(63.75 + 0.5) = 64" 64 Scene.Gamma_off 0.25;
  ch "0.2 → floor(51 + 0.5) = 51" 51 Scene.Gamma_off 0.2;
  ch "1 → 255" 255 Scene.Gamma_off 1.;
  ch "0 → 0" 0 Scene.Gamma_off 0.;
  ch "clip above 1" 255 Scene.Gamma_off 1.7;
  ch "clip below 0" 0 Scene.Gamma_off (-0.3);
  (* 1/255 → floor(1 + 0.5) = 1; 0.5/255 is a half step: floor(0.5 + 0.5) = 1; just below: 0 *)
  ch "1/255" 1 Scene.Gamma_off (1. /. 255.);
  ch "0.4/255" 0 Scene.Gamma_off (0.4 /. 255.)

let test_working_1 () =
  (* sRGB: 1.055·0.5^(1/2.4) − 0.055 = 0.735357; ·255 = 187.516 → 188 *)
  ch "0.5 → 188" 188 (Scene.Working 1.) 0.5;
  ch "1 → 255" 255 (Scene.Working 1.) 1.;
  ch "0 → 0" 0 (Scene.Working 1.) 0.;
  ch "negative → 0" 0 (Scene.Working 1.) (-0.5);
  ch "above 1 → 255" 255 (Scene.Working 1.) 3.;
  (* the linear segment: x ≤ 0.0031308 → 12.92x; 0.002 → 0.02584·255 = 6.589 → 7 *)
  ch "0.002 linear" 7 (Scene.Working 1.) 0.002;
  (* at the boundary both branches give 0.04045·255 = 10.31 → 10 *)
  ch "0.0031308 boundary" 10 (Scene.Working 1.) 0.0031308;
  (* just above: 1.055·0.01^(1/2.4) − 0.055 = 0.099853·255 = 25.46 → 25 *)
  ch "0.01 power law" 25 (Scene.Working 1.) 0.01;
  (* 0.009 is above the threshold: 1.055·0.009^(1/2.4) − 0.055 = 0.093223·255 = 23.77 → 24
     (the linear segment would give 12.92·0.009·255 = 29.65 → 30) *)
  ch "0.009 power law" 24 (Scene.Working 1.) 0.009;
  (* a power law 1/2.2 would give 0.01^(1/2.2)·255 = 31.5: the exact sRGB curve is used *)
  ch "0.2: sRGB 0.484529·255 = 123.55 → 124" 124 (Scene.Working 1.) 0.2

let test_working_22 () =
  (* decode 0.5^2.2 = 0.217638, sRGB 0.503867, ·255 = 128.486 → 128 *)
  ch "0.5 at gamma 2.2" 128 (Scene.Working 2.2) 0.5;
  (* 1^2.2 = 1 → 255; 0 → 0 *)
  ch "1 at gamma 2.2" 255 (Scene.Working 2.2) 1.;
  ch "0 at gamma 2.2" 0 (Scene.Working 2.2) 0.;
  ch "negative at gamma 2.2" 0 (Scene.Working 2.2) (-1.)

let test_image () =
  let img = Image.create 2 1 in
  Image.set img 0 0 0.5 0. 1.;
  Image.set img 1 0 1.5 (-1.) 0.25;
  let e = Encode.image Scene.Gamma_off img in
  Alcotest.(check (pair int int)) "size" (2, 1) (e.width, e.height);
  Alcotest.(check (list int)) "bytes" [ 128; 0; 255; 255; 0; 64 ] (List.init 6 (fun i -> Char.code (Bytes.get e.pixels i)))

let tests =
  [
    Alcotest.test_case "gamma off" `Quick test_gamma_off;
    Alcotest.test_case "working gamma 1" `Quick test_working_1;
    Alcotest.test_case "working gamma 2.2" `Quick test_working_22;
    Alcotest.test_case "image" `Quick test_image;
  ]
