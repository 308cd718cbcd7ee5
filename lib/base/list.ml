(* The library's List: OCaml's, with every function that builds or folds a list in a recursion as
   deep as the list made tail-recursive. A scene of a million objects is a list of a million
   objects; OCaml 4.13's List.map, mapi, map2, append, concat, concat_map, fold_right, fold_right2,
   split and combine would overflow the stack on it. Each keeps OCaml's order of application: f is
   applied to the elements from the first to the last (fold_right: from the last to the first). *)

include Stdlib.List

(* Lists this short go through the plain recursion, faster and allocating nothing extra; longer
   ones are built reversed and turned round. *)
let short = 1000

let map f l =
  let rec direct n = function
    | [] -> []
    | x :: rest when n > 0 ->
        let y = f x in
        y :: direct (n - 1) rest
    | l -> rev (rev_map f l)
  in
  direct short l

let mapi f l =
  let rec direct i = function
    | [] -> []
    | x :: rest when i < short ->
        let y = f i x in
        y :: direct (i + 1) rest
    | l ->
        let rec back i acc = function [] -> rev acc | x :: rest -> back (i + 1) (f i x :: acc) rest in
        back i [] l
  in
  direct 0 l

let map2 f a b =
  if length a <> length b then invalid_arg "List.map2";
  rev (rev_map2 f a b)

let append a b = match b with [] -> a | _ -> rev_append (rev a) b
let concat ls = fold_left (fun acc l -> rev_append l acc) [] ls |> rev
let flatten = concat
let concat_map f l = fold_left (fun acc x -> rev_append (f x) acc) [] l |> rev
let fold_right f l init = fold_left (fun acc x -> f x acc) init (rev l)

let fold_right2 f a b init =
  if length a <> length b then invalid_arg "List.fold_right2";
  fold_left2 (fun acc x y -> f x y acc) init (rev a) (rev b)

let split l =
  let a, b = fold_left (fun (a, b) (x, y) -> (x :: a, y :: b)) ([], []) l in
  (rev a, rev b)

let combine a b =
  if length a <> length b then invalid_arg "List.combine";
  rev (rev_map2 (fun x y -> (x, y)) a b)
