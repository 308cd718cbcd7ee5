(* Property tests (qcheck) of expression evaluation through the interpreter: each property builds a
   small scene whose #debug lines print values, interprets it, and checks the printed values. The
   random state is fixed, so a failure is reproducible. *)

(* Runs [text] and returns the text of its #debug directives. *)
let debug_of text =
  let buf = Buffer.create 64 in
  let opts = { (Interp.default_options ~width:8 ~height:8) with debug = Buffer.add_string buf } in
  ignore (Interp.load_string opts ~file:"p.pov" ("#version 3.7;\n" ^ text));
  Buffer.contents buf

(* A float expression [e] evaluated by the interpreter (printed with 17 decimals). *)
let float_of_expr e = float_of_string (String.trim (debug_of (Printf.sprintf "#debug str(%s, 0, 17)\n" e)))

(* A vector expression [e], as its first three components. *)
let vec_of_expr e =
  let s = debug_of (Printf.sprintf "#declare V_ = %s;\n#debug vstr(3, V_, \",\", 0, 17)\n" e) in
  match List.map float_of_string (String.split_on_char ',' (String.trim s)) with
  | [ x; y; z ] -> Vec.make x y z
  | _ -> failwith ("cannot read a vector from " ^ s)

(* Literals: parenthesised so that negative numbers are safe anywhere. *)
let lit f = Printf.sprintf "(%.17g)" f
let vlit (v : Vec.t) = Printf.sprintf "<%.17g, %.17g, %.17g>" v.x v.y v.z

let close ?(eps = 1e-9) a b = Float.abs (a -. b) <= eps *. Float.max 1. (Float.max (Float.abs a) (Float.abs b))
let vclose ?eps (a : Vec.t) (b : Vec.t) = close ?eps a.x b.x && close ?eps a.y b.y && close ?eps a.z b.z

(* Generators. *)
let gfloat = QCheck.Gen.float_range (-100.) 100.
let gvec = QCheck.Gen.map3 Vec.make gfloat gfloat gfloat
let print_vec (v : Vec.t) = vlit v
let afloat = QCheck.make ~print:(Printf.sprintf "%.17g") gfloat
let avec = QCheck.make ~print:print_vec gvec

let prop ?(count = 100) name arb law =
  let t = QCheck.Test.make ~count ~name arb law in
  Alcotest.test_case name `Quick (fun () -> QCheck.Test.check_exn ~rand:(Random.State.make [| 17 |]) t)

let tests =
  [
    prop "float op vector = promoted float op vector"
      QCheck.(pair afloat avec)
      (fun (f, v) ->
        List.for_all
          (fun op ->
            let a = vec_of_expr (Printf.sprintf "%s %s %s" (lit f) op (vlit v)) in
            let b = vec_of_expr (Printf.sprintf "<%s, %s, %s> %s %s" (lit f) (lit f) (lit f) op (vlit v)) in
            let c = vec_of_expr (Printf.sprintf "%s %s %s" (vlit v) op (lit f)) in
            let d = vec_of_expr (Printf.sprintf "%s %s <%s, %s, %s>" (vlit v) op (lit f) (lit f) (lit f)) in
            vclose a b && vclose c d)
          [ "+"; "-"; "*" ]);
    prop "a shorter vector is padded with zeros"
      QCheck.(pair avec avec)
      (fun (a, b) ->
        let r = vec_of_expr (Printf.sprintf "<%s, %s> + %s" (lit a.x) (lit a.y) (vlit b)) in
        vclose r (Vec.make (a.x +. b.x) (a.y +. b.y) b.z));
    prop "a + b - b = a (floats)"
      QCheck.(pair afloat afloat)
      (fun (a, b) -> close ~eps:1e-12 (float_of_expr (Printf.sprintf "%s + %s - %s" (lit a) (lit b) (lit b))) a);
    prop "a + b - b = a (vectors)"
      QCheck.(pair avec avec)
      (fun (a, b) -> vclose ~eps:1e-12 (vec_of_expr (Printf.sprintf "%s + %s - %s" (vlit a) (vlit b) (vlit b))) a);
    prop "vrotate(V, R) = Transform.rotate R applied to V"
      QCheck.(pair avec avec)
      (fun (v, r) ->
        vclose ~eps:1e-12 (vec_of_expr (Printf.sprintf "vrotate(%s, %s)" (vlit v) (vlit r))) (Transform.point (Transform.rotate r) v));
    prop "vaxis_rotate keeps the length"
      QCheck.(triple avec avec afloat)
      (fun (v, axis, a) ->
        QCheck.assume (Vec.length axis > 1e-3);
        close ~eps:1e-9 (Vec.length (vec_of_expr (Printf.sprintf "vaxis_rotate(%s, %s, %s)" (vlit v) (vlit axis) (lit a)))) (Vec.length v));
    prop "vnormalize has length 1" avec (fun v ->
        QCheck.assume (Vec.length v > 1e-3);
        close ~eps:1e-12 (Vec.length (vec_of_expr (Printf.sprintf "vnormalize(%s)" (vlit v)))) 1.);
    prop "a = div(a, b) * b + mod(a, b)"
      QCheck.(pair afloat afloat)
      (fun (a, b) ->
        QCheck.assume (Float.abs b > 1e-3);
        let q = float_of_expr (Printf.sprintf "div(%s, %s)" (lit a) (lit b)) in
        let m = float_of_expr (Printf.sprintf "mod(%s, %s)" (lit a) (lit b)) in
        Float.is_integer q && Float.abs m < Float.abs b && close ~eps:1e-9 (q *. b +. m) a);
    prop "min and max of any arity"
      QCheck.(list_of_size Gen.(1 -- 8) afloat)
      (fun l ->
        let args = String.concat ", " (List.map lit l) in
        float_of_expr (Printf.sprintf "min(%s)" args) = List.fold_left Float.min (List.hd l) l
        && float_of_expr (Printf.sprintf "max(%s)" args) = List.fold_left Float.max (List.hd l) l);
    prop "select with 3 and 4 arguments"
      QCheck.(quad (oneof [ afloat; always 0. ]) afloat afloat afloat)
      (fun (c, a, b, d) ->
        let s3 = float_of_expr (Printf.sprintf "select(%s, %s, %s)" (lit c) (lit a) (lit b)) in
        let s4 = float_of_expr (Printf.sprintf "select(%s, %s, %s, %s)" (lit c) (lit a) (lit b) (lit d)) in
        s3 = (if c < 0. then a else b) && s4 = if c < 0. then a else if c = 0. then b else d);
    prop "str(v, 0, p) reads back through val within 10^-p"
      QCheck.(pair afloat (int_range 0 9))
      (fun (v, p) ->
        let back = float_of_expr (Printf.sprintf "val(str(%s, 0, %d))" (lit v) p) in
        Float.abs (back -. v) <= (0.5 *. (10. ** float_of_int (-p))) +. 1e-12);
  ]
