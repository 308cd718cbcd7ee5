(* Spline values (Spline, Spline_decl) against POV-Ray 3.7's: the cases of
   test_spline_values_data.ml, made by test/unit/data/spline_values/gen.py, each spline built from
   its entries and read from its block, evaluated with its own kind and with each of the four,
   every term compared with what POV-Ray printed (20 decimals). *)

module D = Test_spline_values_data

let calls = [| None; Some Spline.Linear; Some Spline.Quadratic; Some Spline.Cubic; Some Spline.Natural |]
let call_name = function
  | None -> "S(t)"
  | Some Spline.Linear -> "S(t, linear_spline)"
  | Some Spline.Quadratic -> "S(t, quadratic_spline)"
  | Some Spline.Cubic -> "S(t, cubic_spline)"
  | Some Spline.Natural -> "S(t, natural_spline)"

let kind_name = function
  | Spline.Linear -> "linear" | Quadratic -> "quadratic" | Cubic -> "cubic" | Natural -> "natural"

(* POV-Ray's str(v, 0, 20) *)
let printed x = Printf.sprintf "%.20f" x

(* the value of [s] at every time of [c] for every call, term by term, as POV-Ray printed them (its
   vstr pads the terms past [terms] with zeros) *)
let check_values what (c : D.case) s =
  Alcotest.(check int) (what ^ ": terms") c.terms (Spline.terms s);
  Array.iteri
    (fun m call ->
      let s = match call with None -> s | Some k -> Spline.with_kind s k in
      Array.iteri
        (fun j time ->
          let v = Spline.eval s time in
          Alcotest.(check int) (what ^ ": terms of a value") c.terms (Array.length v);
          let got = Array.init 5 (fun k -> if k < Array.length v then printed v.(k) else printed 0.) in
          Alcotest.(check (array string)) (Printf.sprintf "%s: %s at t = %h" what (call_name call) time) c.printed.(m).(j) got)
        c.times)
    calls

(* the splines of the cases in order, each from its entries (a copy: from the spline it copies) *)
let built =
  lazy
    (let out = Array.make (Array.length D.cases) None in
     Array.iteri
       (fun i (c : D.case) ->
         let s =
           match c.base with
           | None -> Spline.make c.kind c.entries
           | Some b -> (
               match out.(b) with
               | Some base -> Spline.add (Spline.with_kind base c.kind) c.entries
               | None -> Alcotest.failf "case %d copies case %d, not built before it" i b)
         in
         out.(i) <- Some s)
       D.cases;
     Array.map Option.get out)

(* the splines of the cases read from their blocks by Spline_decl, a copy finding the spline it
   names among those read before *)
let read_all () =
  let table = Hashtbl.create 64 in
  Array.map
    (fun (c : D.case) ->
      let st = Interp.reader_state Helpers.opts ~file:"t.pov" (c.preamble ^ c.block) in
      let s = Spline_decl.read_block_with ~named:(fun _ name -> Hashtbl.find_opt table name) st in
      Alcotest.(check bool) (c.label ^ ": the block read to its end") true (Reader.peek st = Token.Eof);
      Hashtbl.replace table c.name s;
      s)
    D.cases

let value_tests =
  Array.to_list
    (Array.mapi
       (fun i (c : D.case) ->
         Alcotest.test_case (Printf.sprintf "%s (%s, %d terms)" c.label (kind_name c.kind) c.terms) `Quick (fun () ->
             check_values c.label c (Lazy.force built).(i)))
       D.cases)

let entries_eq = Alcotest.(array (pair (float 0.) (array (float 0.))))

(* The one difference, not the reader's: POV-Ray keeps a colour identifier in single precision
   (COLC), and its value in a spline is that float; povml's colour identifiers hold doubles. The
   case that uses them is checked to differ by that rounding only. *)
let single_precision entries = Array.map (fun (t, v) -> (t, Array.map Precision.f32 v)) entries

let reader_test () =
  let read = read_all () in
  Array.iteri
    (fun i (c : D.case) ->
      let s = read.(i) and b = (Lazy.force built).(i) in
      Alcotest.(check string) (c.label ^ ": kind read") (kind_name c.kind) (kind_name (Spline.kind s));
      if c.preamble = "" then begin
        Alcotest.check entries_eq (c.label ^ ": entries read") (Spline.entries b) (Spline.entries s);
        check_values (c.label ^ " (read)") c s
      end
      else Alcotest.check entries_eq (c.label ^ ": entries read, colours rounded") (Spline.entries b) (single_precision (Spline.entries s)))
    D.cases

(* ---------------------------------------------------------------------------------------------- *)
(* Rules checked directly (the values above are POV-Ray's; these name the rule each one shows) *)

let sp = Spline.make

let rules () =
  (* entries sorted, a duplicate of the last time lost, of another one replacing *)
  let s = sp Linear [ (1., [| 5. |]); (0., [| 1. |]); (1., [| 9. |]); (0., [| 2. |]) ] in
  Alcotest.check entries_eq "sorted, duplicates" [| (0., [| 2.; 2. |]); (1., [| 5.; 5. |]) |] (Spline.entries s);
  (* the terms past a value's own come from the value written before *)
  let s = sp Linear [ (0., [| 1.; 2.; 3.; 4.; 5. |]); (1., [| 7. |]) ] in
  Alcotest.(check (array (float 0.))) "carried terms" [| 7.; 7.; 3.; 4.; 5. |] (Spline.eval s 1.);
  (* a copy's entries start from a fresh buffer *)
  let s = Spline.add s [ (2., [| 1.; 1. |]) ] in
  Alcotest.(check (array (float 0.))) "fresh buffer in a copy" [| 1.; 1.; 0.; 0.; 0. |] (Spline.eval s 2.);
  (* cubic with two entries: their mean everywhere *)
  let s = sp Cubic [ (0., [| 1. |]); (1., [| 2. |]) ] in
  Alcotest.(check (array (float 0.))) "cubic of two" [| 1.5; 1.5 |] (Spline.eval s (-5.));
  Alcotest.check_raises "no entries" (Invalid_argument "Spline.make: no entries") (fun () -> ignore (sp Linear []))

let read_text text = Spline_decl.read_block (Interp.reader_state Helpers.opts ~file:"t.pov" text)

let reader_rules () =
  (* type keywords: the last before the first entry counts *)
  Alcotest.(check string) "last keyword" "natural" (kind_name (Spline.kind (read_text "{ cubic_spline natural_spline 0, 1 1, 2 }")));
  Alcotest.(check string) "default" "linear" (kind_name (Spline.kind (read_text "{ 0, 1 }")));
  (* times are expressions, commas optional, declared floats start an entry *)
  let s = read_text "#declare T = 3; { (1+1) 4 T, <1, 2, 3>, 4 5 }" in
  Alcotest.check entries_eq "entries"
    [| (2., [| 4.; 4.; 0. |]); (3., [| 1.; 2.; 3. |]); (4., [| 5.; 5.; 3. |]) |] (Spline.entries s);
  Helpers.expect_error "no entry" (fun () -> read_text "{ }") ~line:1 ~col:3 ~sub:"Spline must have at least one entry.";
  Helpers.expect_error "a vector is no time" (fun () -> read_text "{ linear_spline <0, 0>, 1 }") ~line:1 ~col:17
    ~sub:"Spline must have at least one entry.";
  Helpers.expect_error "keyword after an entry" (fun () -> read_text "{ 0, 1 cubic_spline 1, 2 }") ~line:1 ~col:8 ~sub:"cubic_spline";
  Helpers.expect_error "two commas" (fun () -> read_text "{ 0, 1,, 1, 2 }") ~line:1 ~col:8 ~sub:"','";
  Helpers.expect_error "a colour keyword" (fun () -> read_text "{ 0, rgb 1 }") ~line:1 ~col:6 ~sub:"colour keyword 'rgb'";
  Helpers.expect_error "a string" (fun () -> read_text "{ 0, \"a\" }") ~line:1 ~col:6 ~sub:"a string";
  Helpers.expect_error "no brace" (fun () -> read_text "0, 1") ~line:1 ~col:1 ~sub:"{"

let tests =
  value_tests
  @ [
      Alcotest.test_case "read from the blocks: the same splines and values" `Quick reader_test;
      Alcotest.test_case "rules: order, duplicates, terms, few entries" `Quick rules;
      Alcotest.test_case "reader: keywords, commas, errors" `Quick reader_rules;
    ]
