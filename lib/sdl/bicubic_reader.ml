(* The reader of bicubic_patch { … } (POV-Ray's Parse_Bicubic_Patch). *)

open Reader

let c_int x = int_of_float (Expr.c_int x)

let bicubic st loc =
  let patch_type = ref (-1) and flatness = ref 0.0 and u_steps = ref 0 and v_steps = ref 0 in
  let corners = [| 0.; 0.; 1.; 0.; 1.; 1.; 0.; 1. |] in
  let rec loop () =
    match peek st with
    | Ident "type" -> advance st; patch_type := c_int (Expr.parse_float st); loop ()
    | Ident "flatness" -> advance st; flatness := Expr.parse_float st; loop ()
    | Ident "u_steps" -> advance st; u_steps := c_int (Expr.parse_float st); loop ()
    | Ident "v_steps" -> advance st; v_steps := c_int (Expr.parse_float st); loop ()
    | Ident "accuracy" -> advance st; ignore (Expr.parse_float st); loop ()
    | Ident "uv_vectors" ->
        (* four 2-term vectors, the corners' texture coordinates; the points follow *)
        advance st;
        for i = 0 to 3 do
          let u, v = Spline_reader.uv_vector st in
          corners.(2 * i) <- u;
          corners.((2 * i) + 1) <- v;
          if i < 3 then skip_comma st
        done
    | _ when Expr.float_follows st && !patch_type = -1 ->
        (* the old syntax: type, [flatness,] u_steps, v_steps *)
        warn st (peek_loc st) "Should use keywords for bicubic parameters.";
        patch_type := c_int (Expr.parse_float st);
        skip_comma st;
        flatness := if !patch_type = 2 || !patch_type = 3 then (let f = Expr.parse_float st in skip_comma st; f) else 0.1;
        u_steps := c_int (Expr.parse_float st);
        skip_comma st;
        v_steps := c_int (Expr.parse_float st)
    | _ -> ()
  in
  loop ();
  if !patch_type > 1 then begin
    patch_type := 1;
    warn st loc "Patch type no longer supported. Using type 1."
  end;
  if !patch_type < 0 then Error.raise_at loc "Undefined bicubic patch type.";
  skip_comma st;
  let points =
    Array.init 16 (fun k ->
        let p = Expr.parse_vector st in
        if k < 15 then skip_comma st;
        p)
  in
  Scene.Bicubic { patch_type = !patch_type; u_steps = !u_steps; v_steps = !v_steps; flatness = !flatness; points; uv_vectors = corners }
