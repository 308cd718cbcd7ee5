(* Patterns.value against POV-Ray: every pattern at points where POV-Ray printed its value (the
   cases and the scenes are in test_pattern_values_data.ml and test/unit/data/pattern_values/),
   to the last bit: a value must equal POV-Ray's printed 20 decimals within 1e-20. The patterns
   without noise are one suite and those built on Noise another; aoi and slope, which POV-Ray
   evaluates only at an intersection, are checked against their formulas. *)

module D = Test_pattern_values_data

(* what POV-Ray's function printed for a raw value [x] *)
let printed (route : D.route) x =
  let wrap v = if v < 0.0 then v -. floor v else v in
  match route with
  | Raw | Exact -> wrap x
  | Wrapped (f, p) -> wrap (Float.rem ((x *. f) +. p) 1.00001)

let evaluate (c : D.case) (p : Vec.t) =
  let q = match c.warps with [] -> p | ws -> Warp.point ws c.pattern p in
  match c.route with
  | Wrapped (frequency, phase) -> Patterns.value_with ~frequency ~phase c.pattern c.warps c.gen Patterns.no_hit q
  | Raw | Exact -> Patterns.value c.pattern c.warps c.gen Patterns.no_hit q

(* one test per case: all its points, the failures listed together *)
let test_case (c : D.case) =
  Alcotest.test_case c.label `Quick (fun () ->
      let failures =
        List.combine (Array.to_list c.points) (Array.to_list c.values)
        |> List.filter_map (fun ((p : Vec.t), expected) ->
               let got = printed c.route (evaluate c p) in
               if Float.abs (got -. expected) <= 1e-20 then None
               else Some (Printf.sprintf "<%g, %g, %g>: POV-Ray %.20g, povml %.20g" p.x p.y p.z expected got))
      in
      if failures <> [] then Alcotest.failf "%s: %d of %d points differ:\n%s" c.label (List.length failures)
          (Array.length c.points) (String.concat "\n" failures))

(* ---------------------------------------------------------------------------------------------- *)
(* aoi and slope *)

let v = Vec.make
let hit normal dir = { Patterns.normal; dir; uv = Vec.zero }
let value p h q = Patterns.value p [] 2 h q
let close msg expected actual = Alcotest.(check (float 0.)) msg expected actual

let test_aoi () =
  (* acos(n·d)/π with both normalised (VNormalize multiplies by 1/length) *)
  close "head on" 1.0 (value Aoi (hit (v 0. 1. 0.) (v 0. (-1.) 0.)) Vec.zero);
  close "along the surface" 0.5 (value Aoi (hit (v 0. 1. 0.) (v 1. 0. 0.)) Vec.zero);
  let n = Vec.normalize (v 1. 2. 3.) and d = Vec.normalize (v (-1.) 0.5 (-2.)) in
  close "oblique" (acos (Vec.dot (Vec.normalize n) (Vec.normalize d)) /. Float.pi) (value Aoi (hit n d) Vec.zero);
  close "no surface: 0, as POV-Ray's without an intersection" 0. (value Aoi Patterns.no_hit Vec.zero)

let slope ?(altit = Vec.zero) ?(smod = (0., 0.)) ?(amod = (0., 0.)) ?(point_at = false) s =
  let sl = Vec.length s and al = Vec.length altit in
  let norm a l = if l <> 0. then Vec.normalize a else a in
  let total = Precision.f32 (sl +. al) in
  let slope_len, altit_len = if point_at then (1., 0.) else (sl /. total, 1.0 -. (sl /. total)) in
  let base (a : Vec.t) =
    if a.x = 1. then 1 else if a.x = -1. then -1 else if a.y = 1. then 2 else if a.y = -1. then -2
    else if a.z = 1. then 3 else if a.z = -1. then -3 else 0
  in
  let sv = if point_at then s else norm s sl and av = norm altit al in
  Scene.Slope
    {
      slope_vector = sv;
      altit_vector = av;
      slope_base = (if point_at then 0 else base sv);
      altit_base = (if point_at then 0 else base av);
      slope_len;
      altit_len;
      slope_mod = smod;
      altit_mod = amod;
      point_at;
    }

let test_slope () =
  let up = hit (v 0. 1. 0.) (v 0. 0. 1.) in
  (* asin(n·s)/π·2 taken to [0, 1]: facing the slope vector is 1, kept just below it *)
  close "facing y" (1. -. Precision.epsilon) (value (slope (v 0. 1. 0.)) up Vec.zero);
  close "facing −y" 0. (value (slope (v 0. (-1.) 0.)) up Vec.zero);
  close "across" 0.5 (value (slope (v 1. 0. 0.)) up Vec.zero);
  let n = Vec.normalize (v 0.3 0.8 (-0.2)) in
  let s = Vec.normalize (v 3. 4. 0.) in
  let expected = ((asin (Vec.dot n s) /. Float.pi *. 2.) +. 1.0) *. 0.5 in
  close "oblique" expected (value (slope (v 3. 4. 0.)) (hit n (v 0. 0. 1.)) Vec.zero);
  (* a length that is not a float: the lengths' sum is single precision (Tot_Len), so the slope's
     share is not quite 1 and the altitude (here 0) has a tiny share *)
  let s = Vec.normalize (v 1. 1. 0.) in
  let sl = sqrt 2. /. Precision.f32 (sqrt 2.) in
  let raw = ((asin (Vec.dot n s) /. Float.pi *. 2.) +. 1.0) *. 0.5 in
  close "oblique, length √2" (Float.rem ((sl *. raw) +. ((1.0 -. sl) *. 0.)) 1.0) (value (slope (v 1. 1. 0.)) (hit n (v 0. 0. 1.)) Vec.zero);
  (* the short cut for an axis takes the normal's component itself *)
  let e = ((asin n.y /. Float.pi *. 2.) +. 1.0) *. 0.5 in
  close "y, the short cut" e (value (slope (v 0. 1. 0.)) (hit n (v 0. 0. 1.)) Vec.zero);
  let e = ((asin (-.n.z) /. Float.pi *. 2.) +. 1.0) *. 0.5 in
  close "−z, the short cut" e (value (slope (v 0. 0. (-1.))) (hit n (v 0. 0. 1.)) Vec.zero);
  (* low and high slope: (v − low)/(high − low), wrapped *)
  let raw = ((asin n.y /. Float.pi *. 2.) +. 1.0) *. 0.5 in
  close "slope range" (Float.rem ((raw -. 0.5) /. 0.25) 1.0) (value (slope ~smod:(0.5, 0.25) (v 0. 1. 0.)) (hit n (v 0. 0. 1.)) Vec.zero);
  (* with an altitude: the shares of the two lengths, the point's height along it *)
  let q = v 0.2 0.35 (-1.) in
  let p = slope ~altit:(v 0. 2. 0.) (v 0. 1. 0.) in
  let sl = 1. /. Precision.f32 3. in
  let e = (sl *. raw) +. ((1.0 -. sl) *. q.y) in
  close "altitude" (Float.rem e 1.0) (value p (hit n (v 0. 0. 1.)) q);
  let p = slope ~altit:(v 0. 1. 0.) ~amod:(-1., 4.) (v 0. 1. 0.) in
  let e = (0.5 *. raw) +. (0.5 *. ((q.y +. 1.) /. 4.)) in
  close "altitude range" (Float.rem e 1.0) (value p (hit n (v 0. 0. 1.)) q);
  (* point_at: the normal against the direction to the point, from the evaluated point *)
  let target = v 3. 4. 5. in
  let e = ((asin (Vec.dot n (Vec.normalize (Vec.sub target q))) /. Float.pi *. 2.) +. 1.0) *. 0.5 in
  close "point_at" (Float.rem e 1.0) (value (slope ~point_at:true target) (hit n (v 0. 0. 1.)) q);
  close "no surface: 0" 0. (value (slope (v 0. 1. 0.)) Patterns.no_hit Vec.zero)

let test_no_value () =
  let raises p =
    match value p Patterns.no_hit Vec.zero with
    | exception Invalid_argument _ -> ()
    | _ -> Alcotest.fail "expected Invalid_argument"
  in
  raises (Scene.Facets { fsize = 0.1; coords = 0.; fmetric = 2. });
  raises Scene.Average

let tests = List.map test_case D.plain
let surface_tests =
  [
    Alcotest.test_case "aoi" `Quick test_aoi;
    Alcotest.test_case "slope" `Quick test_slope;
    Alcotest.test_case "facets and average have no value" `Quick test_no_value;
  ]

let noise_tests = List.map test_case D.noise
