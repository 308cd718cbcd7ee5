(* Fn_internal: POV-Ray 3.7's internal functions (fnintern.cpp) against the values POV-Ray
   3.7.0.10 printed for test/unit/data/fn_internal.pov (made, with test_fn_internal_data.ml, by
   test/unit/data/fn_internal_gen.py): every function of functions.inc at ten points or more
   (near the origin, on the y axis, negative, far) and several parameter sets each, chosen to
   reach its branches (the field-strength clip, the SOR switch and angle, the cross-section
   types, fractional octaves, the noise generators). POV-Ray prints each value as a mantissa and
   a power of two, so nothing is lost in printing, and every value must be equal to the bit. *)

(* the values of internal(k) at the calls the scene makes of it, in its order: a single
   function per k, as the scene has one declaration, so that f_ridged_mf's first call fixes
   its weights for the others *)
let check_function k () =
  match Fn_internal.make ~noise_generator:2 k with
  | None -> Alcotest.failf "internal(%d) has no implementation" k
  | Some f ->
      let calls = List.filter (fun (j, _, _) -> j = k) (Array.to_list Test_fn_internal_data.calls) in
      if calls = [] then Alcotest.failf "no POV-Ray value for internal(%d)" k;
      List.iteri
        (fun i (_, args, expected) ->
          let actual = f args in
          if not (Float.equal actual expected) then
            Alcotest.failf "%s call %d (%s): POV-Ray %.17g, here %.17g" (Fn_internal.name k) i
              (String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%.17g") args)))
              expected actual)
        calls

let function_tests =
  List.filter_map
    (fun k -> if k = 77 then None else Some (Alcotest.test_case (Fn_internal.name k) `Quick (check_function k)))
    (List.init Fn_internal.count Fun.id)

let table_tests =
  [
    Alcotest.test_case "count, arity and name as POVFPU_TrapTable and functions.inc" `Quick (fun () ->
        Alcotest.(check int) "count" 79 Fn_internal.count;
        Alcotest.(check int) "table size" Fn_internal.count (Array.length Test_fn_internal_data.table);
        Array.iter
          (fun (k, arity, name) ->
            Alcotest.(check int) (Printf.sprintf "arity %d" k) arity (Fn_internal.arity k);
            let name = if name = "" then "f_pattern" else name in
            Alcotest.(check string) (Printf.sprintf "name %d" k) name (Fn_internal.name k))
          Test_fn_internal_data.table);
    Alcotest.test_case "f_pattern has none; every other function has one" `Quick (fun () ->
        for k = 0 to Fn_internal.count - 1 do
          Alcotest.(check bool) (Fn_internal.name k) (k <> 77)
            (Option.is_some (Fn_internal.make ~noise_generator:2 k))
        done;
        Alcotest.(check bool) "out of range" true (Option.is_none (Fn_internal.make ~noise_generator:2 79)));
    Alcotest.test_case "f_noise3d uses the scene's noise_generator" `Quick (fun () ->
        Array.iter
          (fun (gen, args, expected) ->
            match Fn_internal.make ~noise_generator:gen 76 with
            | None -> Alcotest.fail "f_noise3d"
            | Some f -> Alcotest.(check (float 0.)) (Printf.sprintf "generator %d" gen) expected (f args))
          Test_fn_internal_data.noise3d);
    Alcotest.test_case "the argument array is not written" `Quick (fun () ->
        for k = 0 to Fn_internal.count - 1 do
          match Fn_internal.make ~noise_generator:2 k with
          | None -> ()
          | Some f ->
              let args = Array.init (Fn_internal.arity k + 2) (fun i -> 0.0 +. (0.125 *. float i)) in
              args.(0) <- 0.;
              args.(2) <- 0.;
              let copy = Array.copy args in
              ignore (f args);
              Alcotest.(check (array (float 0.))) (Fn_internal.name k) copy args
        done);
  ]

let tests = table_tests @ function_tests
