(* Function bodies compiled into closures, with the code fncode.cpp chooses. *)

open Fn

type code = float array -> float

(* What a body can see while compiling: the parameters, the x y z registers and the [sum]/[prod]
   counters open around the current expression (the innermost first). *)
type env = {
  params : string array;
  counters : (string * int) list;
  next_slot : int ref;  (** the next free frame slot for a counter *)
  warn : Loc.t -> string -> unit;
  floc : Loc.t;  (** where the function starts, for errors at constants (which have no location) *)
  counted : bool;  (** the code takes its steps from {!Fn_budget} (for calls while the scene is read) *)
}

let c_int = C_float.int_cast

(* The last parameter named [a] or [b] (compile_parameters loads them in order, later ones win). *)
let register params a b =
  let found = ref None in
  Array.iteri (fun i p -> if p = a || p = b then found := Some i) params;
  !found

let slot_of env name loc : code =
  let from = function Some i -> fun fr -> fr.(i) | None -> fun _ -> 0. in
  match name with
  | "x" | "u" -> from (register env.params "x" "u")
  | "y" | "v" -> from (register env.params "y" "v")
  | "z" -> from (register env.params "z" "z")
  | _ -> (
      match List.assoc_opt name env.counters with
      | Some i -> fun fr -> fr.(i)
      | None -> (
          match List.find_opt (fun i -> env.params.(i) = name) (List.init (Array.length env.params) Fun.id) with
          | Some i -> fun fr -> fr.(i)
          | None -> Error.raise_at loc "unknown identifier '%s' in a function: expected a parameter or a declared float" name))

let bool b = if b then 1. else 0.

(* [a op b] for an operand that is not a constant. *)
let binop op (a : code) (b : code) : code =
  match op with
  | Add -> fun fr -> let l = a fr in l +. b fr
  | Sub -> fun fr -> let l = a fr in l -. b fr
  | Mul -> fun fr -> let l = a fr in l *. b fr
  | Div -> fun fr -> let l = a fr in l /. b fr
  | Pow -> fun fr -> let l = a fr in Float.pow l (b fr)
  | Eq -> fun fr -> let l = a fr in bool (l = b fr)
  | Ne -> fun fr -> let l = a fr in bool (l <> b fr)
  | Lt -> fun fr -> let l = a fr in bool (l < b fr)
  | Le -> fun fr -> let l = a fr in bool (l <= b fr)
  | Gt -> fun fr -> let l = a fr in bool (l > b fr)
  | Ge -> fun fr -> let l = a fr in bool (l >= b fr)
  | Or -> fun fr -> let l = a fr in let r = b fr in bool (Fn_optimise.truth l +. Fn_optimise.truth r <> 0.)
  | And -> fun fr -> let l = a fr in let r = b fr in Fn_optimise.truth l *. Fn_optimise.truth r

(* pow(a, n) for the exponents the compiler writes out as products. *)
let power (a : code) n : code option =
  match n with
  | 2. -> Some (fun fr -> let x = a fr in x *. x)
  | 3. -> Some (fun fr -> let x = a fr in x *. x *. x)
  | 4. -> Some (fun fr -> let x = a fr in let x2 = x *. x in x2 *. x2)
  | 5. -> Some (fun fr -> let x = a fr in let x2 = x *. x in x2 *. x2 *. x)
  | 6. -> Some (fun fr -> let x = a fr in let x2 = x *. x in x2 *. x2 *. x2)
  | 7. -> Some (fun fr -> let x = a fr in let x2 = x *. x in x2 *. x2 *. x *. x2)
  | 8. -> Some (fun fr -> let x = a fr in let x2 = x *. x in let x4 = x2 *. x2 in x4 *. x4)
  | _ -> None

let rec code env e : code =
  match e with
  | Const c -> fun _ -> c
  | Var (name, loc) -> slot_of env name loc
  | Paren e -> code env e
  | Neg e -> let a = code env e in fun fr -> -.a fr
  | Chain (first, rest) -> List.fold_left (step env) (code env first) rest
  | Builtin (f, args, loc) -> builtin env f args loc
  | Call (f, args, _) -> call env f args
  | Member (f, args, m, _) -> member env f args m

(* One operator of a chain applied to the value so far. *)
and step env (acc : code) (op, e) : code =
  match (op, e) with
  | Add, Const c -> if c <> 0. then fun fr -> acc fr +. c else acc
  | Sub, Const c -> if c <> 0. then fun fr -> acc fr -. c else acc
  | Mul, Const c -> if c <> 1. then fun fr -> acc fr *. c else acc
  | Div, Const c ->
      if c = 0. then Error.raise_at (expr_loc env e) "division by zero in a function"
      else if c <> 1. then let k = 1. /. c in fun fr -> acc fr *. k
      else acc
  | Pow, Const 0. ->
      env.warn (expr_loc env e) "zero power optimised to constant 1.0";
      fun _ -> 1.
  | Pow, Const n when power acc n <> None -> Option.get (power acc n)
  | _ -> binop op acc (code env e)

and expr_loc env = function
  | Var (_, loc) | Builtin (_, _, loc) | Call (_, _, loc) | Member (_, _, _, loc) -> loc
  | Paren e | Neg e | Chain (e, _) -> expr_loc env e
  | Const _ -> env.floc

and builtin env f args loc : code =
  let one g = match args with [ a ] -> let a = code env a in fun fr -> g (a fr) | _ -> Error.raise_at loc "this function takes one parameter" in
  let two g =
    match args with [ a; b ] -> let a = code env a and b = code env b in fun fr -> let r = b fr in g (a fr) r | _ -> Error.raise_at loc "this function takes two parameters"
  in
  match f with
  | Sin -> one sin
  | Cos -> one cos
  | Tan -> one tan
  | Asin -> one asin
  | Acos -> one acos
  | Atan -> one atan
  | Sinh -> one sinh
  | Cosh -> one cosh
  | Tanh -> one tanh
  | Asinh -> one Float.asinh
  | Acosh -> one Float.acosh
  | Atanh -> one Float.atanh
  | Abs -> one Float.abs
  | Radians -> let k = Float.pi /. 180. in one (fun x -> x *. k)
  | Degrees -> let k = 180. /. Float.pi in one (fun x -> x *. k)
  | Int -> one c_int
  | Floor -> one Float.floor
  | Ceil -> one Float.ceil
  | Sqrt -> one Float.sqrt
  | Exp -> one Float.exp
  | Ln -> one Float.log
  | Log -> one Float.log10
  | Sqr -> one (fun x -> x *. x)
  | Atan2 -> two Float.atan2
  | Pow_call -> two Float.pow
  | Mod -> two Float.rem
  | Div_call -> two (fun a b -> c_int (a /. b))
  | Min | Max -> extremum env (f = Min) args loc
  | Select -> select env args loc
  | Sum | Prod -> loop env (f = Sum) args loc

(* min and max over two or more parameters, kept as the VM compares them: min keeps the new value
   unless it is greater than or equal to the one so far; max keeps it only when it is greater. *)
and extremum env is_min args loc =
  match List.map (code env) args with
  | first :: (_ :: _ as rest) ->
      let pick (acc : code) (next : code) : code =
        if is_min then fun fr -> let last = acc fr in let cur = next fr in if cur > last || cur = last then last else cur
        else fun fr -> let last = acc fr in let cur = next fr in if cur > last then cur else last
      in
      List.fold_left pick first rest
  | _ -> Error.raise_at loc "this function takes at least two parameters"

(* select(c, a, b): a when c < 0, else b; select(c, a, b, d): a when c < 0, b when c = 0, else d. *)
and select env args loc =
  match List.map (code env) args with
  | [ c; a; b ] -> fun fr -> if c fr < 0. then a fr else b fr
  | [ c; a; b; d ] -> fun fr -> let v = c fr in if v < 0. then a fr else if v = 0. then b fr else d fr
  | _ -> Error.raise_at loc "select takes three or four parameters"

(* sum(i, from, to, e) and prod(…): the counter runs from [from] by steps of 1 while it is at most [to]. *)
and loop env is_sum args loc =
  match args with
  | [ Var (name, _); from; upto; body ] ->
      let from = code env from and upto = code env upto in
      let k = !(env.next_slot) in
      incr env.next_slot;
      let steps = operations body in
      let body = code { env with counters = (name, k) :: env.counters } body in
      let neutral = if is_sum then 0. else 1. in
      (* the counting code takes the body's steps before each iteration; the renderer's does not *)
      let body = if env.counted then fun fr -> Fn_budget.take steps; body fr else body in
      fun fr ->
        fr.(k) <- from fr;
        let stop = upto fr in
        let acc = ref neutral in
        while fr.(k) <= stop do
          let v = body fr in
          acc := if is_sum then !acc +. v else !acc *. v;
          fr.(k) <- fr.(k) +. 1.
        done;
        !acc
  | [ _; _; _; _ ] -> Error.raise_at loc "the first parameter of sum and prod is the name of its counter"
  | _ -> Error.raise_at loc "sum and prod take four parameters"

and args_code env args = Array.of_list (List.map (code env) args)

and call env f args : code =
  let a = args_code env args in
  let n = Array.length a in
  let size = max f.frame 3 in
  let eval = if env.counted then Lazy.force f.counted else f.eval in
  match a with
  | [| a0; a1; a2 |] when size = 3 ->
      (* a literal array of three floats is allocated in line, without a call into the runtime *)
      fun fr ->
        let x0 = a0 fr in
        let x1 = a1 fr in
        let x2 = a2 fr in
        eval [| x0; x1; x2 |]
  | _ ->
      (* Every other call site owns the callee's frame: a function can only call functions declared
         before it, so a site is never re-entered while its callee runs (and each worker is a
         process). The arguments are written in order; the slots after them belong to the
         callee's sum and prod counters, which set them before reading them. *)
      let c = Array.make size 0. in
      fun fr ->
        for i = 0 to n - 1 do
          Array.unsafe_set c i (a.(i) fr)
        done;
        eval c

(* a fresh frame for the callee: the arguments in order, the rest 0 (Array.create_float, not
   Array.make, which asks the runtime what kind of value 0. is at every call) *)
and frame_of a n size fr =
  let c = Array.create_float size in
  for i = 0 to n - 1 do
    Array.unsafe_set c i (a.(i) fr)
  done;
  for i = n to size - 1 do
    Array.unsafe_set c i 0.
  done;
  c

and member env f args m : code =
  let a = args_code env args in
  let size = max f.frame 3 in
  let veval = f.veval in
  let n = Array.length a in
  let terms fr = veval (frame_of a n size fr) in
  match m with
  | -1 -> fun fr -> let t = terms fr in (t.(0) *. red_to_gray) +. (t.(1) *. green_to_gray) +. (t.(2) *. blue_to_gray)
  | -2 -> let k = 1. /. 255. in fun fr -> let t = terms fr in (t.(0) +. (t.(1) *. k)) *. 0.996093
  | i -> fun fr -> let t = terms fr in if i < Array.length t then t.(i) else 0.

(* The steps an evaluation of [e] takes from the budget: its operations (numbers, variables,
   operators and calls), a sum's or prod's body once. *)
and operations e =
  let all = List.fold_left (fun n e -> n + operations e) 0 in
  match e with
  | Const _ | Var _ -> 1
  | Paren e | Neg e -> 1 + operations e
  | Chain (first, rest) -> operations first + all (List.map snd rest)
  | Builtin (_, args, _) | Call (_, args, _) | Member (_, args, _, _) -> 1 + all args

let no_vector _ = [||]

let compile ~name ~params ~loc ~warn body =
  let body = Fn_optimise.optimise body in
  let env counted warn = { params; counters = []; next_slot = ref (Array.length params); warn; floc = loc; counted } in
  let plain = env false warn in
  let eval = code plain body in
  (* the counting code, compiled again when first called (its warnings were given above); an
     entry takes the body's operations, each sum or prod iteration its own *)
  let counted =
    lazy
      (let steps = operations body and run = code (env true (fun _ _ -> ())) body in
       fun fr -> Fn_budget.take steps; run fr)
  in
  { name; params; frame = !(plain.next_slot); size = 0; eval; veval = no_vector; counted; floc = loc }
