(* TrueType reading for the text object (docs/povray-rules.md §15.9), following the steps of POV-Ray's
   truetype.cpp: ProcessFontFile, ProcessCharMap, ExtractGlyphOutline, ProcessNewTTF. *)

exception Bad of string

type kern = { coverage : int; pairs : (int * int * int) array (* left, right, value *) }

type t = {
  data : string;
  cmap : int;
  glyf : int;
  units_per_em : int;
  loca : int array;
  advance : int array;
  lsb : int array;
  kerns : kern array;
}

let truncated () = raise (Bad "the file ends inside a table (cannot read the TrueType font)")
let u8 s o = if o < 0 || o >= String.length s then truncated () else Char.code s.[o]
let u16 s o = (u8 s o lsl 8) lor u8 s (o + 1)
let s16 s o = let v = u16 s o in if v >= 0x8000 then v - 0x10000 else v
let u32 s o = (u16 s o lsl 16) lor u16 s (o + 2)

let units_per_em f = f.units_per_em

let parse data =
  try
    let s = data in
    if String.length s < 12 then raise (Bad "it is too short to be a TrueType font");
    (* a TrueType collection: its first font *)
    let base = if String.sub s 0 4 = "ttcf" then u32 s 8 else 0 in
    let ntables = u16 s (base + 4) in
    let find tag =
      let rec go i =
        if i >= ntables || i >= 40 then 0
        else
          let e = base + 12 + (16 * i) in
          if e + 16 > String.length s then truncated ()
          else if String.sub s e 4 = tag then u32 s (e + 8)
          else go (i + 1)
      in
      go 0
    in
    let cmap = find "cmap" and glyf = find "glyf" and head = find "head" and loca = find "loca" in
    let maxp = find "maxp" and kern = find "kern" and hhea = find "hhea" and hmtx = find "hmtx" in
    List.iter
      (fun (tag, o) -> if o = 0 then raise (Bad (Printf.sprintf "it has no '%s' table: not a TrueType font with outlines" tag)))
      [ ("cmap", cmap); ("glyf", glyf); ("head", head); ("loca", loca); ("hhea", hhea); ("hmtx", hmtx); ("maxp", maxp) ];
    if u32 s (head + 12) <> 0x5F0F3CF5 then raise (Bad "its head table has the wrong magic number (cannot read the TrueType font)");
    let units_per_em = u16 s (head + 18) in
    let loc_format = s16 s (head + 50) in
    if (loc_format <> 0 && loc_format <> 1) || units_per_em < 16 || units_per_em > 16384 then
      raise (Bad "its head table is invalid (units per em or location format)");
    let nglyphs = u16 s (maxp + 4) in
    if nglyphs <= 0 then raise (Bad "it has no glyphs");
    let loca = Array.init nglyphs (fun i -> if loc_format = 0 then u16 s (loca + (2 * i)) lsl 1 else u32 s (loca + (4 * i))) in
    let nmetrics = u16 s (hhea + 34) in
    if nmetrics <= 0 then raise (Bad "its hhea table has no horizontal metrics");
    let advance = Array.make nglyphs 0 and lsb = Array.make nglyphs 0 in
    let last = ref 0 and o = ref hmtx in
    for i = 0 to nglyphs - 1 do
      if i < nmetrics then begin
        last := u16 s !o;
        advance.(i) <- !last;
        lsb.(i) <- s16 s (!o + 2);
        o := !o + 4
      end
      else begin
        advance.(i) <- !last;
        lsb.(i) <- s16 s !o;
        o := !o + 2
      end
    done;
    let kerns =
      if kern = 0 then [||]
      else begin
        let n = u16 s (kern + 2) in
        let o = ref (kern + 4) in
        Array.init n (fun _ ->
            let length = u16 s (!o + 2) and coverage = u16 s (!o + 4) in
            if coverage lsr 8 = 0 then begin
              let np = u16 s (!o + 6) in
              let p0 = !o + 14 in
              let pairs = Array.init np (fun j -> let e = p0 + (6 * j) in (u16 s e, u16 s (e + 2), s16 s (e + 4))) in
              o := p0 + (6 * np);
              { coverage; pairs }
            end
            else begin
              o := !o + length;
              { coverage; pairs = [||] }
            end)
      end
    in
    Ok { data; cmap; glyf; units_per_em; loca; advance; lsb; kerns }
  with Bad m -> Error m

(* ProcessCharMap: the platforms in the order searched, for ASCII strings (Macintosh first) and
   for UTF-8 ones (Unicode first); the first table of a matching platform in a supported format
   answers. *)
let platforms ~utf8 = if utf8 then [ 0; 3; 1; 3 ] else [ 1; 3; 0; 3 ]

let format4 s sub c =
  let segx2 = u16 s (sub + 6) in
  let seg = segx2 / 2 in
  let ends = sub + 14 in
  let starts = ends + segx2 + 2 in
  let deltas = starts + segx2 in
  let ranges = deltas + segx2 in
  let search c =
    let rec go i =
      if i >= seg then 0
      else if c <= u16 s (ends + (2 * i)) then begin
        if c >= u16 s (starts + (2 * i)) then begin
          let ro = u16 s (ranges + (2 * i)) and delta = u16 s (deltas + (2 * i)) in
          if ro = 0 then (c + delta) land 0xffff
          else
            let g = u16 s (ranges + (2 * i) + ro + (2 * (c - u16 s (starts + (2 * i))))) in
            if g <> 0 then (g + delta) land 0xffff else 0
        end
        else 0
      end
      else go (i + 1)
    in
    go 0
  in
  let g = search c in
  if g = 0 && c < 0x100 then search (c + 0xF000) else g

let glyph_index_exn ~utf8 f c =
  let s = f.data in
  let count = u16 s (f.cmap + 2) in
  let rec tables plats =
    match plats with
    | [] -> 0
    | p :: rest ->
        let rec entry i =
          if i >= count then tables rest
          else
            let e = f.cmap + 4 + (8 * i) in
            if u16 s e <> p then entry (i + 1)
            else
              let sub = f.cmap + u32 s (e + 4) in
              match u16 s sub with
              | 0 -> u8 s (sub + 6 + c)
              | 4 -> format4 s sub c
              | 6 ->
                  let first = u16 s (sub + 6) and n = u16 s (sub + 8) in
                  if c >= first && c < first + n then u16 s (sub + 10 + (2 * (c - first))) else 0
              | _ -> entry (i + 1)
        in
        entry 0
  in
  tables (platforms ~utf8)

let glyph_index ?(utf8 = false) f c = try glyph_index_exn ~utf8 f c with Bad _ -> 0

(* ExtractGlyphOutline: the points (em units) with their flags, the contours' last points, the
   header's box (font units) widened by the points, and the glyph whose metrics it uses. *)
type raw = {
  mutable nc : int;
  mutable xmin : int;
  mutable ymin : int;
  mutable xmax : int;
  mutable ymax : int;
  mutable ends : int list; (* reversed *)
  mutable pts : (float * float * int) list; (* reversed *)
  mutable npts : int;
  mutable metrics : int;
}

(* What one character's outline may cost: a composite glyph names others, up to 8 deep, each of
   which may name many, so that a small hostile file could ask for an exponential number of glyphs
   and points. No real font comes near these. *)
type budget = { mutable glyphs : int; mutable points : int }

let max_glyphs = 10_000
let max_points = 1_000_000

let rec extract f g c depth budget =
  if depth > 8 then raise (Bad "its composite glyphs nest too deep");
  budget.glyphs <- budget.glyphs + 1;
  if budget.glyphs > max_glyphs then raise (Bad (Printf.sprintf "a composite glyph is made of more than %d glyphs" max_glyphs));
  let s = f.data in
  let r = { nc = 0; xmin = 0; ymin = 0; xmax = 0; ymax = 0; ends = []; pts = []; npts = 0; metrics = g } in
  if g < 0 || g >= Array.length f.loca then raise (Bad (Printf.sprintf "glyph %d is not in the font" g));
  if c <> 32 then begin
    let o = f.glyf + f.loca.(g) in
    r.nc <- s16 s o;
    r.xmin <- s16 s (o + 2);
    r.ymin <- s16 s (o + 4);
    r.xmax <- s16 s (o + 6);
    r.ymax <- s16 s (o + 8);
    let upem = float_of_int f.units_per_em in
    if r.nc > 0 then begin
      let nc = r.nc in
      let ends = Array.init nc (fun i -> u16 s (o + 10 + (2 * i))) in
      let ins = u16 s (o + 10 + (2 * nc)) in
      let p = ref (o + 12 + (2 * nc) + ins) in
      let n = ends.(nc - 1) + 1 in
      budget.points <- budget.points + n;
      if budget.points > max_points then raise (Bad (Printf.sprintf "a glyph has more than %d points" max_points));
      let flags = Array.make n 0 in
      let i = ref 0 in
      while !i < n do
        let fl = u8 s !p in
        incr p;
        flags.(!i) <- fl;
        if fl land 8 <> 0 then begin
          let rep = u8 s !p in
          incr p;
          for _ = 1 to rep do
            if !i < n - 1 then flags.(!i + 1) <- flags.(!i);
            incr i
          done
        end;
        incr i
      done;
      let coords short pos =
        let v = Array.make n 0 in
        let co = ref 0 in
        for i = 0 to n - 1 do
          let fl = flags.(i) in
          if fl land short <> 0 then begin
            let b = u8 s !p in
            incr p;
            if fl land pos <> 0 then co := !co + b else co := !co - b
          end
          else if fl land pos = 0 then begin
            co := !co + s16 s !p;
            p := !p + 2
          end;
          (* the coordinate is a 16-bit FWord *)
          co := ((!co + 0x8000) land 0xffff) - 0x8000;
          v.(i) <- !co
        done;
        v
      in
      let xs = coords 2 0x10 in
      let ys = coords 4 0x20 in
      Array.iter (fun x -> if x > r.xmax then r.xmax <- x; if x < r.xmin then r.xmin <- x) xs;
      Array.iter (fun y -> if y > r.ymax then r.ymax <- y; if y < r.ymin then r.ymin <- y) ys;
      r.ends <- List.rev (Array.to_list ends);
      r.pts <- List.rev (List.init n (fun i -> (float_of_int xs.(i) /. upem, float_of_int ys.(i) /. upem, flags.(i))));
      r.npts <- n
    end
    else if r.nc < 0 then begin
      r.nc <- 0;
      let p = ref (o + 10) in
      let more = ref true in
      while !more do
        let flags = u16 s !p and sub = u16 s (!p + 2) in
        p := !p + 4;
        let arg1, arg2 =
          if flags land 1 <> 0 then (let a = s16 s !p and b = s16 s (!p + 2) in p := !p + 4; (a, b))
          else (let a = u16 s !p in p := !p + 2; ((a lsr 8) land 0xff, a land 0xff))
        in
        let f2 () = let v = float_of_int (s16 s !p) /. 16384. in p := !p + 2; v in
        let xscale, s01, s10, yscale =
          if flags land 8 <> 0 then (let v = f2 () in (v, 0., 0., v))
          else if flags land 0x40 <> 0 then (let a = f2 () in let b = f2 () in (a, 0., 0., b))
          else if flags land 0x80 <> 0 then (let a = f2 () in let b = f2 () in let c = f2 () in let d = f2 () in (a, b, c, d))
          else (1., 0., 0., 1.)
        in
        more := flags land 0x20 <> 0;
        if flags land 2 <> 0 then begin
          let xoff = float_of_int arg1 /. upem and yoff = float_of_int arg2 /. upem in
          if flags land 0x200 <> 0 then r.metrics <- sub;
          let sr = extract f sub c (depth + 1) budget in
          if sr.nc <> 0 then begin
            let n = r.npts in
            budget.points <- budget.points + sr.npts;
            if budget.points > max_points then raise (Bad (Printf.sprintf "a glyph has more than %d points" max_points));
            r.ends <- List.rev_append (List.rev_map (fun e -> e + n) sr.ends) r.ends;
            r.npts <- r.npts + sr.npts;
            r.nc <- r.nc + sr.nc;
            List.iter
              (fun (x, y, fl) ->
                let x' = (xscale *. x) +. (s01 *. y) +. xoff and y' = (s10 *. x) +. (yscale *. y) +. yoff in
                (* the header is in font units but compared with em units, and stored truncated
                   (a double assigned to a SHORT), as POV-Ray does *)
                if x' < float_of_int r.xmin then r.xmin <- truncate x';
                if x' > float_of_int r.xmax then r.xmax <- truncate x';
                if y' < float_of_int r.ymin then r.ymin <- truncate y';
                if y' > float_of_int r.ymax then r.ymax <- truncate y';
                r.pts <- (x', y', fl) :: r.pts)
              (List.rev sr.pts)
          end
        end
      done
    end
  end;
  r

let outline f g ~char_code =
  try
    let r = extract f g char_code 0 { glyphs = 0; points = 0 } in
    let pts = Array.of_list (List.rev r.pts) in
    let _, contours =
      List.fold_left
        (fun (first, acc) e ->
          let n = e - first + 1 in
          if n <= 0 || first + n > Array.length pts then raise (Bad "a glyph's contours are out of order");
          let sub = Array.sub pts first n in
          let xs = Array.map (fun (x, _, _) -> x) sub and ys = Array.map (fun (_, y, _) -> y) sub in
          let on = Array.map (fun (_, _, fl) -> fl land 1 <> 0) sub in
          (e + 1, (xs, ys, on) :: acc))
        (0, []) (List.rev r.ends)
    in
    let o =
      Glyph.outline_of_contours ~units_per_em:f.units_per_em ~xmin:r.xmin ~ymin:r.ymin ~xmax:r.xmax ~ymax:r.ymax (List.rev contours)
    in
    Ok (o, r.metrics)
  with Bad m -> Error m

(* the kerning of the pair (left glyph, right glyph's metrics): every horizontal subtable's pair
   values, though the coverage is read from the first subtable for all (as POV-Ray does) *)
let kerning f ~left ~right =
  let upem = f.units_per_em in
  let kx = ref 0 and ky = ref 0 and kminx = ref (-upem) and kminy = ref (-upem) in
  Array.iteri
    (fun _ (tb : kern) ->
      let coverage = f.kerns.(0).coverage in
      if coverage land 1 <> 0 then begin
        let exception Stop in
        try
          Array.iter
            (fun (l, r, v) ->
              if l = left && r = right then begin
                (if coverage land 2 <> 0 then (if coverage land 4 <> 0 then kminy := v else kminx := v)
                 else if coverage land 4 <> 0 then (if v = -0x8000 then ky := 0 else if coverage land 8 <> 0 then ky := v else ky := !ky + v)
                 else if coverage land 8 <> 0 then kx := v
                 else kx := !kx + v);
                raise Stop
              end
              else if l > left then raise Stop)
            tb.pairs
        with Stop -> ()
      end)
    f.kerns;
  let wrap v = ((v + 0x8000) land 0xffff) - 0x8000 in
  let kx = wrap !kx and ky = wrap !ky in
  ((if kx > !kminx then kx else !kminx), if ky > !kminy then ky else !kminy)

let layout ?(utf8 = false) f codes ~offset =
  let funit = 1.0 /. float_of_int f.units_per_em in
  (* the glyphs already read: by character first, then by glyph index (ProcessCharacter) *)
  let cache = ref [] in
  let get c =
    match List.find_opt (fun (c', _, _, _) -> c' = c) !cache with
    | Some (_, g, o, m) -> Ok (g, o, m)
    | None -> (
        let g = glyph_index ~utf8 f c in
        match List.find_opt (fun (_, g', _, _) -> g' = g) !cache with
        | Some (_, g, o, m) -> Ok (g, o, m)
        | None -> (
            match outline f g ~char_code:c with
            | Ok (o, m) ->
                cache := (c, g, o, m) :: !cache;
                Ok (g, o, m)
            | Error e -> Error e))
  in
  let n = Array.length codes in
  let rec go i (tx, ty, tz) last acc =
    if i >= n then Ok (List.rev acc)
    else
      match get codes.(i) with
      | Error e -> Error e
      | Ok (g, (o : Glyph.outline), m) ->
          let m = if m < Array.length f.advance then m else 0 in
          let aw = f.advance.(m) and lsb = f.lsb.(m) in
          let place, (tx, ty) =
            if i = 0 then
              let x = float_of_int (-o.xmin) *. funit in
              (Vec.make x 0. 0., (float_of_int (aw - lsb) *. funit, ty))
            else
              let kx, ky = if Array.length f.kerns = 0 then (0, 0) else kerning f ~left:last ~right:m in
              let lx = tx +. (float_of_int (lsb - o.xmin + kx) *. funit) and ly = ty +. (float_of_int ky *. funit) in
              (Vec.make lx ly 0., (tx +. (float_of_int (aw + kx) *. funit), ty))
          in
          let t = (tx +. offset.Vec.x, ty +. offset.y, tz +. offset.z) in
          go (i + 1) t g ((o, place) :: acc)
  in
  go 0 (0., 0., 0.) 0 []
