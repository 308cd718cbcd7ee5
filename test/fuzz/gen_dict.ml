(* Writes the AFL++ dictionary (one quoted token a line) from the mutator's tokens, so the two
   fuzzers insert the same words and the list follows the interpreter's own keyword lists. *)

let escape s =
  let b = Buffer.create (String.length s) in
  String.iter
    (fun c ->
      match c with
      | '"' | '\\' -> Buffer.add_char b '\\'; Buffer.add_char b c
      | c when Char.code c < 32 || Char.code c > 126 -> Buffer.add_string b (Printf.sprintf "\\x%02x" (Char.code c))
      | c -> Buffer.add_char b c)
    s;
  Buffer.contents b

let () =
  List.iteri (fun i t -> Printf.printf "t%d=\"%s\"\n" i (escape t)) (List.sort_uniq compare Povml_fuzz.Mutate.tokens)
