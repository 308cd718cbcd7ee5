(* Fn_budget: the steps user functions take while the scene is read (issue 34: a sum of 10¹² terms
   and 64 functions each calling the one before twice ran until killed). *)

open Helpers

let compile params body = Fn_compile.compile ~name:"F" ~params ~loc:Loc.none ~warn:(fun _ _ -> ()) body

(* sum(i, 1, n, i) of the parameter n *)
let sum_to_n =
  compile [| "n" |] (Fn.Builtin (Sum, [ Var ("i", Loc.none); Const 1.; Var ("n", Loc.none); Var ("i", Loc.none) ], Loc.none))

let test_steps () =
  Fn_budget.start 1_000_000;
  float_eq "a call within the budget" 5050. (Fn.call sum_to_n [| 100. |]);
  Fn_budget.start 1_000;
  (match Fn.call sum_to_n [| 1e12 |] with
  | v -> Alcotest.failf "a sum of 1e12 terms within 1,000 steps gave %g" v
  | exception Fn_budget.Exhausted -> ());
  (* the renderer's code does not count: the spent budget does not stop it *)
  float_eq "eval does not count" 5050. (sum_to_n.eval [| 100.; 0. |]);
  Fn_budget.start max_int

(* each of 64 functions calls the one before twice: 2^63 calls, stopped by the budget *)
let test_calls () =
  let x = Fn.Var ("x", Loc.none) in
  let f0 = compile [| "x" |] (Chain (x, [ (Add, Const 1.) ])) in
  let rec chain f k = if k = 0 then f else chain (compile [| "x" |] (Chain (Call (f, [ x ], Loc.none), [ (Add, Call (f, [ x ], Loc.none)) ]))) (k - 1) in
  let f63 = chain f0 63 and f3 = chain f0 3 in
  Fn_budget.start 1_000_000;
  float_eq "F3(0) = 8" 8. (Fn.call f3 [| 0. |]);
  (match Fn.call f63 [| 0. |] with
  | v -> Alcotest.failf "2^63 calls within 1,000,000 steps gave %g" v
  | exception Fn_budget.Exhausted -> ());
  Fn_budget.start max_int

(* [text] read under [limits] stops with a limit error at [where] ([at], line and column) that
   names [switch] *)
let expect_limit limits text ~where ~at ~switch =
  match Interp.load_string { opts with limits } ~file:"t.pov" text with
  | _ -> Alcotest.fail "expected a limit error"
  | exception Error.Scene_error e ->
      Alcotest.(check (pair int int)) where at (e.loc.line, e.loc.col);
      Alcotest.(check bool) "a limit" true (e.kind = Limit);
      check_contains "the switch" ~sub:switch e.msg

(* from the scene language: a limit error at the call, naming the switch *)
let test_scene () =
  expect_limit { Scene_limits.default with function_steps = 10_000 }
    "#declare F = function(n) { sum(i, 1, n, 1/(i*i)) }\n#declare A = F(10);\n#declare B = F(1e12);\n"
    ~where:"at the call" ~at:(3, 14) ~switch:"--max-function-steps"

(* strings built by the string functions, all together *)
let test_strings () =
  expect_limit { Scene_limits.default with string_mb = 1 }
    "#declare S = \"\";\n#for (I, 1, 100000) #declare S = concat(S, \"x\"); #end\n"
    ~where:"at concat" ~at:(2, 34) ~switch:"--max-strings"

let tests =
  [
    Alcotest.test_case "a sum counted" `Quick test_steps;
    Alcotest.test_case "calls counted" `Quick test_calls;
    Alcotest.test_case "a located limit error" `Quick test_scene;
    Alcotest.test_case "strings built" `Quick test_strings;
  ]
