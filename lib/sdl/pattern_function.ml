(* Pattern functions. *)

open Reader

(* the pattern keyword (a block pattern's too, without its list), then the modifiers *)
let header st loc =
  let h =
    match Materials.block_pattern st None with
    | Some (pattern, _) -> advance st; { Pattern_reader.plain with pat = Some pattern }
    | None -> (
        match Pattern_reader.pattern_keyword st Pattern_reader.Pigment_pattern Pattern_reader.plain with
        | Some h -> h
        | None -> unexpected st "a pattern in the pattern function")
  in
  let rec loop h = match Pattern_reader.modifier st h with Some h -> loop h | None -> h in
  Pattern_reader.finish st loc (loop h)

let point fr = Vec.make fr.(0) fr.(1) fr.(2)

let pattern st floc =
  open_block st "pattern";
  let loc = peek_loc st in
  let h = header st loc in
  close_block st "pattern";
  let pat = Option.get h.pat in
  let eval fr =
    let gen = if h.noise = 0 then st.noise_generator else h.noise in
    let q = Warp.point h.warps pat (point fr) in
    Pigment.shape_value ~frequency:h.frequency ~phase:h.phase h.wave
      (Patterns.value_with ~frequency:h.frequency ~phase:h.phase pat h.warps gen Patterns.no_hit q)
  in
  { Fn.name = ""; params = [| "x"; "y"; "z" |]; frame = 3; size = 0; eval; veval = (fun _ -> [||]); counted = Lazy.from_val eval; floc }
