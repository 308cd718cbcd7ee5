(* Reading functions: the body grammar of fnsyntax.cpp, declarations, and calls from the scene
   language. *)

open Token
open Reader

let builtins =
  Fn.
    [ ("sin", Sin); ("cos", Cos); ("tan", Tan); ("asin", Asin); ("acos", Acos); ("atan", Atan); ("sinh", Sinh);
      ("cosh", Cosh); ("tanh", Tanh); ("asinh", Asinh); ("acosh", Acosh); ("atanh", Atanh); ("abs", Abs);
      ("radians", Radians); ("degrees", Degrees); ("int", Int); ("floor", Floor); ("ceil", Ceil); ("sqrt", Sqrt);
      ("exp", Exp); ("ln", Ln); ("log", Log); ("min", Min); ("max", Max); ("atan2", Atan2); ("pow", Pow_call);
      ("mod", Mod); ("div", Div_call); ("select", Select); ("sum", Sum); ("prod", Prod) ]

let registers = [ "x"; "y"; "z"; "u"; "v" ]

let members =
  [ ("x", 0); ("u", 0); ("red", 0); ("y", 1); ("v", 1); ("green", 1); ("z", 2); ("blue", 2); ("t", 3); ("filter", 3);
    ("transmit", 4); ("gray", -1); ("grey", -1); ("hf", -2) ]

let noise_generator st = st.noise_generator

(* One precedence level: operands of [next] joined by the operators of [ops], left to right. *)
let max_chain = 65536

let level ops next st name =
  let first = next st name in
  let rec more acc n =
    match List.assq_opt (peek st) ops with
    | Some op ->
        (* a chain is evaluated by nested closures: its length is bounded to keep the stack safe *)
        if n >= max_chain then Error.limit_at (peek_loc st) "a function has more than %s operators in a row, povml's limit" (commas max_chain);
        advance st;
        more ((op, next st name) :: acc) (n + 1)
    | None -> List.rev acc
  in
  match more [] 0 with [] -> first | rest -> Fn.Chain (first, rest)

let rec expr st name = level [ (Bar, Fn.Or) ] conj st name
and conj st name = level [ (Amp, Fn.And) ] compare st name
and compare st name = level Fn.[ (Eq, Eq); (Ne, Ne); (Lt, Lt); (Le, Le); (Gt, Gt); (Ge, Ge) ] sum st name
and sum st name = level Fn.[ (Plus, Add); (Minus, Sub) ] product st name
and product st name = level Fn.[ (Star, Mul); (Slash, Div) ] signed st name

and signed st name =
  let loc = peek_loc st in
  match peek st with
  | Minus -> advance st; Fn.Neg (nest st loc (fun () -> operand st name))
  | Plus -> advance st; operand st name
  | Bang -> Error.raise_at loc "'!' cannot be used in a function (use 1 - (…) or select)"
  | _ -> operand st name

and operand st name =
  let loc = peek_loc st in
  match peek st with
  | Num c -> advance st; Fn.Const c
  | LParen ->
      advance st;
      let e = nest st loc (fun () -> expr st name) in
      expect st RParen "')' closing the parenthesis";
      Fn.Paren e
  | Ident s when List.mem s registers -> advance st; Fn.Var (s, loc)
  | Ident "pi" -> advance st; Fn.Const Float.pi
  | Ident "clock" -> advance st; Fn.Const st.opts.clock
  | Ident s when List.mem_assoc s builtins && cur_value st s = None ->
      advance st;
      let f = List.assoc s builtins in
      let args = arguments st name s in
      check_builtin loc s f args;
      Fn.Builtin (f, args, loc)
  | Ident s -> identifier st name loc s
  | _ -> unexpected st "an operand in the function (a number, a parameter, a declared float or a function call)"

and identifier st name loc s =
  match cur_value st s with
  | Some (V.Float c) -> advance st; Fn.Const c
  | Some (V.Function f) ->
      if s = name then Error.raise_at loc "recursive function calls are not allowed: '%s' calls itself" s;
      advance st;
      let args = arguments st name s in
      let n = List.length args in
      if n <> Fn.arity f then
        Error.raise_notes loc [ (f.floc, Printf.sprintf "'%s' is declared here" s) ]
          (Printf.sprintf "the function '%s' takes %d parameter%s, but %d %s given" s (Fn.arity f)
             (if Fn.arity f = 1 then "" else "s") n (if n = 1 then "was" else "were"));
      if f.size = 0 then Fn.Call (f, args, loc)
      else begin
        expect st Dot (Printf.sprintf "'.' and a member after the vector function '%s' (as in .x or .red)" s);
        let mloc = peek_loc st in
        match peek st with
        | Ident m when List.mem_assoc m members -> advance st; Fn.Member (f, args, List.assoc m members, loc)
        | _ ->
            ignore mloc;
            unexpected st "a member: x, y, z, t, u, v, red, green, blue, gray, grey, filter or transmit"
      end
  | Some (V.Unsupported u) -> unsupported_use loc s u.what u.at
  | Some v -> Error.raise_at loc "'%s' is %s, but a function can use only floats and functions" s (V.kind_name v)
  | None when is_unsupported s -> not_supported loc (Printf.sprintf "'%s'" s)
  | None when is_keyword s -> Error.raise_at loc "'%s' cannot be used in a function" s
  | None ->
      advance st;
      if peek st == LParen then
        Error.raise_at loc "'%s' is not a declared function (an internal function needs #include \"functions.inc\")" s;
      Fn.Var (s, loc)

and arguments st name what =
  let loc = peek_loc st in
  nest st loc (fun () -> arguments_in st name what)

and arguments_in st name what =
  expect st LParen (Printf.sprintf "'(' after '%s'" what);
  let rec more acc =
    let a = expr st name in
    if accept st Comma then more (a :: acc) else List.rev (a :: acc)
  in
  let args = more [] in
  expect st RParen (Printf.sprintf "')' closing the parameters of '%s'" what);
  args

and check_builtin loc s f args =
  let n = List.length args in
  let want lo hi = if n < lo || n > hi then
      Error.raise_at loc "'%s' takes %s, but %d %s given" s
        (if lo = hi then Printf.sprintf "%d parameter%s" lo (if lo = 1 then "" else "s") else Printf.sprintf "%d to %d parameters" lo hi)
        n (if n = 1 then "was" else "were") in
  match f with
  | Fn.Min | Fn.Max -> if n < 2 then want 2 2
  | Fn.Atan2 | Fn.Pow_call | Fn.Mod | Fn.Div_call -> want 2 2
  | Fn.Select -> want 3 4
  | Fn.Sum | Fn.Prod -> want 4 4
  | _ -> want 1 1

let body st ~name = expr st name

let compile st ~name ~params ~loc e = Fn_compile.compile ~name ~params ~loc ~warn:(fun l m -> warn st l "%s" m) e

let anonymous st =
  let loc = peek_loc st in
  open_block st "function";
  let e = body st ~name:"" in
  close_block st "function";
  compile st ~name:"" ~params:[| "x"; "y"; "z" |] ~loc e

let params st =
  if peek st != LParen then [| "x"; "y"; "z" |]
  else begin
    advance st;
    let rec more acc =
      let loc = peek_loc st in
      let p =
        match peek_name st with
        | Ident s when List.mem s registers -> s
        | Ident s when is_keyword s -> Error.raise_at loc "expected a parameter name but found the keyword '%s'" s
        | Ident s -> (
            match cur_value st s with
            | None -> s
            | Some v -> Error.raise_at loc "expected a parameter name but '%s' is %s (a parameter cannot be a declared identifier)" s (V.kind_name v))
        | _ -> unexpected st "a parameter name"
      in
      advance st;
      if accept st Comma then more (p :: acc) else List.rev (p :: acc)
    in
    let ps = more [] in
    expect st RParen "')' closing the parameters";
    Array.of_list ps
  end

(* internal(k): one of POV-Ray's built-in functions, with its own parameter count *)
let internal st ~name ~written loc =
  advance st;
  expect st LParen "'(' after 'internal'";
  let kloc = peek_loc st in
  let k = match peek st with Num k -> advance st; k | _ -> unexpected st "the number of an internal function" in
  expect st RParen "')' after the number of the internal function";
  let k = int_of_float k in
  if k < 0 || k >= Fn_internal.count then Error.raise_at kloc "function 'internal(%d)' does not exist" k;
  match Fn_internal.make ~noise_generator:(noise_generator st) k with
  | None -> not_supported kloc (Printf.sprintf "the internal function '%s' (internal(%d))" (Fn_internal.name k) k)
  | Some eval ->
      ignore written;
      let n = Fn_internal.arity k in
      let params = Array.init n (fun i -> match i with 0 -> "x" | 1 -> "y" | 2 -> "z" | i -> Printf.sprintf "p%d" (i - 3)) in
      (* a call while the scene is read takes as many steps as the function loops, before it runs *)
      let counted =
        match Fn_internal.loop_parameter k with
        | None -> Lazy.from_val eval
        | Some i -> Lazy.from_val (fun fr -> Fn_budget.take (Fn_budget.loops fr.(i)); eval fr)
      in
      { Fn.name; params; frame = n; size = 0; eval; veval = (fun _ -> [||]); counted; floc = loc }

let declaration st ~name ~special =
  let loc = peek_loc st in
  let written = peek st == LParen in
  let ps = params st in
  open_block st "function";
  let f =
    match peek st with
    | Ident "internal" -> internal st ~name ~written loc
    | Ident kw when (match cur_value st kw with None -> true | Some _ -> false) && List.mem kw [ "pigment"; "transform"; "pattern"; "spline" ] -> (
        let kloc = peek_loc st in
        if written then Error.raise_at kloc "a %s function cannot have parameters" kw;
        match special kw kloc with
        | Some f -> { f with Fn.name; floc = loc }
        | None -> not_supported kloc (Printf.sprintf "'%s' functions" kw))
    | _ ->
        let e = body st ~name in
        compile st ~name ~params:ps ~loc e
  in
  close_block st "function";
  V.Function f

let sdl_call st (f : Fn.t) loc ~parse_float =
  advance st;
  let n = Fn.arity f in
  let what = if f.name = "" then "the function" else Printf.sprintf "'%s'" f.name in
  expect st LParen (Printf.sprintf "'(' and the %d parameters of %s" n what);
  let args =
    Array.init n (fun i ->
        if i > 0 then expect st Comma (Printf.sprintf "',' and parameter %d of %d of %s" (i + 1) n what);
        parse_float st)
  in
  if peek st == Comma then Error.raise_at (peek_loc st) "%s takes %d parameter%s" what n (if n = 1 then "" else "s");
  expect st RParen (Printf.sprintf "')' after the %d parameters of %s" n what);
  if f.size = 0 then V.Float (with_function_steps st loc (fun () -> Fn.call f args))
  else
    let t = Fn.call_vector f args in
    if Array.length t = 5 then V.Colour t else if Array.length t = 1 then V.Float t.(0) else V.Vector t
