(* A small structure-aware mutator. Scene text is mostly words between blanks, so besides AFL-style
   byte changes it inserts whole words of the language at word boundaries and repeats runs, which
   reaches the interpreter's deeper states (directives, macros, nesting) far more often than random
   bytes do. *)

let punctuation =
  [ "{"; "}"; "("; ")"; "<"; ">"; "["; "]"; ","; ";"; "="; "+"; "-"; "*"; "/"; "."; "!"; "!="; "<="; ">=";
    "&"; "|"; "?"; ":"; "\""; "/*"; "*/"; "//"; "\\"; "#" ]

let numbers =
  [ "0"; "1"; "-1"; "2"; "3"; "0.5"; ".5"; "1."; "-0"; "255"; "256"; "1000000"; "1e308"; "1e-308"; "1e400";
    "-1e400"; "1e-400"; "2147483647"; "2147483648"; "-2147483649"; "4294967296"; "9007199254740993";
    "12345678901234567890"; "1e"; "1e+"; "0.000000000001" ]

let snippets =
  [ "#declare A = 1;"; "#local B = <1, 2, 3>;"; "#declare C = \"s\";"; "#macro M(a) a #end"; "M(1)";
    "#declare i = 0; #while (i < 3) #declare i = i + 1; #end"; "#for (j, 0, 3) #end";
    "#if (1) #else #end"; "#switch (1) #case (1) #break #range (0, 2) #else #end";
    "#declare R = array[3] {1, 2, 3};"; "R[1]"; "R[3]"; "#declare R[0] = 2;"; "#undef A"; "#ifdef (A) #end";
    "#ifndef (A) #end"; "str(1, 0, 0)"; "vstr(3, <1,2,3>, \",\", 0, 1)"; "concat(\"a\", \"b\")";
    "substr(\"abc\", 2, 1)"; "chr(65)"; "#include \"colors.inc\""; "#version 3.7;"; "sphere { 0, 1 }";
    "plane { y, 0 }"; "pigment { rgb 1 }"; "texture { pigment { rgb <1, 0, 0> } }";
    "light_source { <0, 5, -5> rgb 1 }"; "camera { location <0, 1, -5> look_at 0 }";
    "global_settings { assumed_gamma 1 }"; "union { sphere { 0, 1 } sphere { x, 1 } }";
    "mesh { triangle { 0, x, y } }";
    "mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }"; "object { A }";
    "#default { finish { ambient 0.1 } }"; "defined(A)"; "dimensions(R)"; "dimension_size(R, 1)";
    "seed(1)"; "rand(S)"; "#declare S = seed(7);" ]

let tokens =
  Interp.keywords @ Reader.unsupported @ Expr.function_names
  @ List.map (fun d -> "#" ^ d) Directives.directive_names
  @ punctuation @ numbers @ snippets

let token_array = Array.of_list tokens
let pick rng a = a.(Random.State.int rng (Array.length a))

(* A position at a word boundary near [p]: the next blank at or after it, else the end. *)
let boundary text p =
  let n = String.length text in
  let rec go i = if i >= n then n else match text.[i] with ' ' | '\n' | '\t' -> i | _ -> go (i + 1) in
  go p

(* A run [start, start + len) of [text], of length 1 … [max_len]. *)
let run rng text max_len =
  let n = String.length text in
  let len = 1 + Random.State.int rng (max 1 (min max_len n)) in
  let start = Random.State.int rng (max 1 (n - len + 1)) in
  (start, min len (n - start))

let insert text p s = String.sub text 0 p ^ s ^ String.sub text p (String.length text - p)
let delete text p len = String.sub text 0 p ^ String.sub text (p + len) (String.length text - p - len)

(* Bytes a changed byte becomes: punctuation more often than any other byte. *)
let special = "{}()<>[],;=+-*/.!&|?:\"#\\ \n0123456789xyz"

let random_byte rng =
  if Random.State.bool rng then special.[Random.State.int rng (String.length special)]
  else Char.chr (Random.State.int rng 256)

let once rng ~seeds text =
  let n = String.length text in
  let pos () = Random.State.int rng (n + 1) in
  match Random.State.int rng 11 with
  | 0 when n > 0 ->
      (* one byte changed *)
      let b = Bytes.of_string text in
      Bytes.set b (Random.State.int rng n) (random_byte rng);
      Bytes.to_string b
  | 1 when n > 0 -> let p, len = run rng text 64 in delete text p len
  | 2 when n > 0 -> let p, len = run rng text 128 in insert text (pos ()) (String.sub text p len)
  | 3 ->
      (* a run of another seed *)
      let other = pick rng seeds in
      if other = "" then text else let p, len = run rng other 256 in insert text (boundary text (pos ())) (String.sub other p len)
  | 4 -> String.sub text 0 (Random.State.int rng (n + 1))
  | 5 | 6 | 7 -> insert text (boundary text (pos ())) (" " ^ pick rng token_array ^ " ")
  | 8 -> insert text (pos ()) (pick rng token_array)
  | 9 ->
      (* deep nesting or a long run: an opener (or a short run) repeated many times *)
      let unit = match Random.State.int rng 4 with 0 -> "(" | 1 -> "{" | 2 -> "<" | _ -> if n = 0 then "[" else let p, len = run rng text 8 in String.sub text p len in
      insert text (pos ()) (String.concat "" (List.init (1 + Random.State.int rng 4000) (fun _ -> unit)))
  | _ when n > 0 ->
      (* a number replaced by an awkward one *)
      let p = Random.State.int rng n in
      let rec digit i = if i >= n then None else match text.[i] with '0' .. '9' -> Some i | _ -> digit (i + 1) in
      (match digit p with
      | None -> text
      | Some i ->
          let rec stop j = if j < n && (match text.[j] with '0' .. '9' | '.' -> true | _ -> false) then stop (j + 1) else j in
          let j = stop i in
          insert (delete text i (j - i)) i (pick rng (Array.of_list numbers)))
  | _ -> insert text 0 (pick rng token_array)

let mutate rng ~seeds text =
  let k = 1 + Random.State.int rng 4 in
  let rec go i t = if i = 0 then t else go (i - 1) (once rng ~seeds t) in
  go k text
