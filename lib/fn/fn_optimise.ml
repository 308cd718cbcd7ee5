(* POV-Ray's constant folding of function bodies (optimise_expr in fnsyntax.cpp). *)

open Fn

let rec has_var = function
  | Const _ -> false
  | Var _ -> true
  | Paren e | Neg e -> has_var e
  | Chain (e, rest) -> has_var e || List.exists (fun (_, e) -> has_var e) rest
  | Builtin (_, args, _) | Call (_, args, _) | Member (_, args, _, _) -> List.exists has_var args

let truth x = if x <> 0. then 1. else 0.

(* The value of [l op r], as the folding computes it (the logical operators as the VM does). *)
let fold op l r =
  let b c = if c then 1. else 0. in
  match op with
  | Eq -> b (l = r)
  | Ne -> b (l <> r)
  | Lt -> b (l < r)
  | Le -> b (l <= r)
  | Gt -> b (l > r)
  | Ge -> b (l >= r)
  | Add -> l +. r
  | Sub -> l -. r
  | Or -> b (truth l +. truth r <> 0.)
  | Mul -> l *. r
  | Div -> l /. r
  | And -> truth l *. truth r
  | Pow -> Float.pow l r

let rec optimise e =
  match e with
  | Const _ | Var _ -> e
  | Paren e -> Paren (optimise e)
  | Neg e -> ( match optimise e with Const c -> Const (-.c) | e -> Neg e)
  | Chain (first, rest) -> chain first rest
  | Builtin (Pow_call, [ a; b ], _) -> Paren (chain a [ (Pow, b) ])
  | Builtin (f, a :: rest, loc) -> Builtin (f, optimise a :: rest, loc)
  | Call (f, a :: rest, loc) -> Call (f, optimise a :: rest, loc)
  | Member (f, a :: rest, m, loc) -> Member (f, optimise a :: rest, m, loc)
  | Builtin (_, [], _) | Call (_, [], _) | Member (_, [], _, _) -> e

(* One chain: [done_] holds the elements kept so far, the last first; its head's operand is the
   left operand of the next operator. *)
and chain first rest =
  let first = optimise first in
  let step (done_, seen_var) (op, e) =
    let op, e = match (op, e) with Sub, Const c -> (Add, Const (-.c)) | _ -> (op, e) in
    let e = optimise e in
    let seen_var = seen_var || has_var e in
    match (done_, e) with
    | (lop, Const l) :: kept, Const r when (op <> Mul && op <> Div) || not seen_var -> ((lop, Const (fold op l r)) :: kept, seen_var)
    | _ -> ((Some op, e) :: done_, seen_var)
  in
  let done_, _ = List.fold_left step ([ (None, first) ], has_var first) rest in
  match List.rev done_ with
  | [ (None, Const c) ] -> Const c
  | (None, first) :: rest -> Chain (first, List.map (fun (op, e) -> (Option.get op, e)) rest)
  | _ -> assert false
