(* The corners of triangles, and the mesh and mesh2 objects (docs/povray-rules.md §2.4–§2.6). *)

open Token
open Reader
open Expr
open Materials

(* Vertex normals: normalised; a zero normal becomes <1,0,0> with a warning (§2.6). *)
let unit_normal st loc (n : Vec.t) =
  if Vec.length n = 0. then begin
    warn st loc "zero-length normal replaced by <1,0,0>";
    Vec.make 1. 0. 0.
  end
  else Vec.normalize n


(* A vector written as plain numbers, read without tokens (Lexer.scan_vector3) into [out]: true
   when that worked, and the parser then stands after the '>'. *)
let fast_vector3 st out =
  (* the '<' was read from the current frame, so the numbers are in the same text *)
  peek st == Lt && Lexer.scan_vector3 (top st).lx out && begin st.have <- false; true end

(* A vector of a mesh: by the fast path when it is written as plain numbers. *)
let mesh_vector st =
  let buf = [| 0.; 0.; 0. |] in
  if fast_vector3 st buf then Vec.make buf.(0) buf.(1) buf.(2) else parse_vector st

(* triangle { P1, P2, P3 } and smooth_triangle { P1, N1, P2, N2, P3, N3 } (§2.4, §2.5). *)
let triangle_corners st ~smooth =
  let p1 = mesh_vector st in
  skip_comma st;
  if smooth then begin
    let l1 = peek_loc st in
    let n1 = mesh_vector st in
    skip_comma st;
    let p2 = mesh_vector st in
    skip_comma st;
    let l2 = peek_loc st in
    let n2 = mesh_vector st in
    skip_comma st;
    let p3 = mesh_vector st in
    skip_comma st;
    let l3 = peek_loc st in
    let n3 = mesh_vector st in
    (p1, p2, p3, Some (unit_normal st l1 n1, unit_normal st l2 n2, unit_normal st l3 n3))
  end
  else begin
    let p2 = mesh_vector st in
    skip_comma st;
    let p3 = mesh_vector st in
    (p1, p2, p3, None)
  end

(* A UV vector <u, v> (Parse_UV_Vect: a float stands for both; more than two terms is an error). *)
let uv_vector st =
  let loc = peek_loc st in
  match parse_expr st with
  | V.Float f -> (f, f)
  | V.Vector [| u; v |] -> (u, v)
  | v -> Error.raise_at loc "expected a UV vector <u, v> but found %s" (V.kind_name v)

(* The UV coordinates of a mesh { } as POV-Ray's Mesh_Hash_UV keeps them: a pair within EPSILON
   (1e-10) in each term of one already in its hash bucket is that one; the values stay in double
   precision. *)
type uv_table = { buckets : (int, (float * float * int) list) Hashtbl.t; values : float Growable.t; mutable count : int }

let uv_table () = { buckets = Hashtbl.create 256; values = Growable.create 0.; count = 0 }

let uv_index t (u, v) =
  let bucket = (C_float.c_int (326.0 *. u) lxor C_float.c_int (694.7 *. v)) land 0xFFFFFFFF mod 1000 in
  let entries = Option.value (Hashtbl.find_opt t.buckets bucket) ~default:[] in
  match List.find_opt (fun (pu, pv, _) -> Float.abs (pu -. u) < Precision.epsilon && Float.abs (pv -. v) < Precision.epsilon) entries with
  | Some (_, _, i) -> i
  | None ->
      let i = t.count in
      Hashtbl.replace t.buckets bucket (entries @ [ (u, v, i) ]);
      Growable.push t.values u;
      Growable.push t.values v;
      t.count <- i + 1;
      i

(* uv_vectors UV1, UV2, UV3 after a mesh triangle's corners (Parse_Three_UVCoords) *)
let three_uvs st =
  let a = uv_vector st in
  skip_comma st;
  let b = uv_vector st in
  skip_comma st;
  let c = uv_vector st in
  (a, b, c)

(* A block "{ n, item, item … }" of a mesh2: [item] is called for each entry (with its location),
   and the number of entries must be n. *)
let parse_counted_block ?(start = fun (_ : int) -> ()) st what item =
  let loc = peek_loc st in
  open_block st what;
  let nloc = peek_loc st in
  let n = parse_float st in
  if n < 0. || Float.of_int (int_of_float n) <> n then Error.raise_at nloc "the count of %s must be a whole number, not %g" what n;
  let n = int_of_float n in
  (* room for the announced entries, within reason: a wrong count is reported after the block, and
     a count that lies must not take the memory (an entry takes at most 4 words: half the limit) *)
  start (min n (min 50_000_000 (st.opts.limits.memory_mb * 1048576 / 64)));
  let count = ref 0 in
  while peek st != RBrace do
    if peek st == Eof then close_block st what;
    skip_comma st;
    if peek st != RBrace then begin
      item (peek_loc st);
      incr count
    end
  done;
  advance st;
  if !count <> n then Error.raise_at loc "%s says %d entries but lists %d" what n !count;
  n

let f32_vec (v : Vec.t) = Vec.make (Precision.f32 v.x) (Precision.f32 v.y) (Precision.f32 v.z)

let parse_texture_in_block st =
  (* texture { … } or a texture identifier inside a mesh triangle *)
  advance st;
  Texture_reader.parse st

(* mesh { triangle {…} smooth_triangle {…} … [inside_vector V] modifiers } (§2.6), read up to the
   modifiers. Vertices are kept in single precision; each face is set up from the values as parsed. *)
let mesh st loc =
  open_shape st "mesh";
  let verts = Vertex_table.create () and norms = Vertex_table.create () and corners = Growable.create 0. in
  let fv = Growable.create 0 and fn = Growable.create 0 and ftex = Growable.create 0 in
  let textures = ref [] and ntex = ref 0 in
  let inside = ref None in
  (* UV coordinates are stored from the first triangle that has uv_vectors on; the triangles
     before it get (0, 0) at every corner then, as POV-Ray gives every triangle without them *)
  let uvs = uv_table () and fuv = ref None and ntri = ref 0 in
  let push3 g (v : Vec.t) = Growable.push g v.x; Growable.push g v.y; Growable.push g v.z in
  let add_vertex (v : Vec.t) = Growable.push fv (Vertex_table.insert verts (Precision.f32 v.x) (Precision.f32 v.y) (Precision.f32 v.z)) in
  let add_normal (n : Vec.t) = Growable.push fn (Vertex_table.insert norms (Precision.f32 n.x) (Precision.f32 n.y) (Precision.f32 n.z)) in
  let rec items () =
    match peek st with
    | Ident ("triangle" | "smooth_triangle" as kw) ->
        advance st;
        open_block st kw;
        let p1, p2, p3, ns = triangle_corners st ~smooth:(kw = "smooth_triangle") in
        let zero = (0., 0.) in
        let corner_uvs = if accept_ident st "uv_vectors" then Some (three_uvs st) else None in
        (match (corner_uvs, !fuv) with
        | None, None -> ()
        | Some _, None ->
            let g = Growable.create ~capacity:(3 * (!ntri + 1)) 0 in
            if !ntri > 0 then begin
              let z = uv_index uvs zero in
              for _ = 1 to 3 * !ntri do Growable.push g z done
            end;
            fuv := Some g
        | (Some _ | None), Some _ -> ());
        (match !fuv with
        | None -> ()
        | Some g ->
            let a, b, c = Option.value corner_uvs ~default:(zero, zero, zero) in
            Growable.push g (uv_index uvs a);
            Growable.push g (uv_index uvs b);
            Growable.push g (uv_index uvs c));
        incr ntri;
        let tex =
          if is_ident st "texture" then begin
            (* POV-Ray takes only a texture identifier here: texture { T } *)
            advance st;
            open_block st "texture";
            let tl = peek_loc st in
            let t =
              match ident_of_kind st (function V.Texture t -> Some t | _ -> None) with
              | Some t -> t
              | None -> Error.raise_at tl "expected a texture identifier: a mesh triangle takes texture { Identifier }"
            in
            close_block st "texture";
            textures := t :: !textures;
            incr ntex;
            !ntex - 1
          end
          else -1
        in
        close_block st kw;
        add_vertex p1; add_vertex p2; add_vertex p3;
        push3 corners p1; push3 corners p2; push3 corners p3;
        (match ns with
        | Some (a, b, c) -> add_normal a; add_normal b; add_normal c
        | None -> Growable.push fn (-1); Growable.push fn (-1); Growable.push fn (-1));
        Growable.push ftex tex;
        items ()
    | Ident "inside_vector" -> advance st; inside := Some (parse_vector st); items ()
    | _ -> ()
  in
  items ();
  let uvs, fuv = match !fuv with None -> ([||], [||]) | Some g -> (Growable.to_array uvs.values, Growable.to_array g) in
  let mesh =
    Mesh.build_uv ~uvs ~fuv ~vertices:(Vertex_table.to_array verts) ~vertex_normals:(Vertex_table.to_array norms)
      ~fv:(Growable.to_array fv) ~fn:(Growable.to_array fn) ~ftex:(Growable.to_array ftex) ~corners:(Some (Growable.to_array corners))
      ~inside_vector:!inside
  in
  if mesh.faces = 0 then warn st loc "the mesh has no triangles with an area";
  Scene.Mesh { mesh; trans = None; textures = Array.of_list (List.rev !textures) }

(* mesh2 { vertex_vectors normal_vectors texture_list face_indices normal_indices inside_vector … },
   read up to the modifiers *)
let mesh2 st loc =
  open_shape st "mesh2";
  let vertices = ref None and normals = ref None and textures = ref [||] in
  let faces = ref None and nidx = ref None and inside = ref None in
  let uvs = ref None and uvidx = ref None in
  let vectors what ~unit =
    let g = ref (Growable.create 0.) in
    let n =
      parse_counted_block st what ~start:(fun n -> g := Growable.create ~capacity:(3 * n) 0.) (fun l ->
          let g = !g in
          let v = mesh_vector st in
          let v = f32_vec (if unit then unit_normal st l v else v) in
          Growable.push g v.x; Growable.push g v.y; Growable.push g v.z)
    in
    (n, Growable.to_array !g)
  in
  let indices st l limit what g =
    let v = mesh_vector st in
    let check x =
      if Float.of_int (int_of_float x) <> x || x < 0. || int_of_float x >= limit then
        Error.raise_at l "%s index %g is out of range: there are %d" what x limit;
      Growable.push g (int_of_float x)
    in
    check v.x; check v.y; check v.z
  in
  (* a block of index triples below [limit]: where it was written, its count, the indices *)
  let index_block name l limit what =
    let g = ref (Growable.create 0) in
    let n = parse_counted_block st name ~start:(fun n -> g := Growable.create ~capacity:(3 * n) 0) (fun l -> indices st l limit what !g) in
    (l, n, Growable.to_array !g)
  in
  let rec sections () =
    let l = peek_loc st in
    match peek st with
    | Ident "vertex_vectors" -> advance st; vertices := Some (vectors "vertex_vectors" ~unit:false); sections ()
    | Ident "normal_vectors" -> advance st; normals := Some (vectors "normal_vectors" ~unit:true); sections ()
    | Ident "uv_vectors" ->
        advance st;
        if !uvs <> None then warn st l "duplicate uv_vectors block; ignoring previous block";
        let g = ref (Growable.create 0.) in
        let n =
          parse_counted_block st "uv_vectors" ~start:(fun n -> g := Growable.create ~capacity:(2 * n) 0.) (fun _ ->
              let u, v = uv_vector st in
              Growable.push !g u;
              Growable.push !g v)
        in
        uvs := Some (n, Growable.to_array !g);
        sections ()
    | Ident "texture_list" ->
        advance st;
        let g = ref [] in
        ignore
          (parse_counted_block st "texture_list" (fun l ->
               if is_ident st "texture" then g := parse_texture_in_block st :: !g
               else Error.raise_at l "expected a texture in texture_list"));
        textures := Array.of_list (List.rev !g);
        sections ()
    | Ident "face_indices" ->
        advance st;
        let nv = match !vertices with Some (n, _) -> n | None -> Error.raise_at l "face_indices before vertex_vectors" in
        let ntex = Array.length !textures in
        let fv = ref (Growable.create 0) and ftex = ref (Growable.create 0) in
        let n =
          parse_counted_block st "face_indices"
            ~start:(fun n ->
              fv := Growable.create ~capacity:(3 * n) 0;
              (* per-face texture indices only when there is a texture list *)
              if ntex > 0 then ftex := Growable.create ~capacity:n 0)
            (fun l ->
              let fv = !fv and ftex = !ftex in
              indices st l nv "vertex" fv;
              (* an optional texture index (three would interpolate, which is not read yet) *)
              let tex =
                (* POV-Ray's CASE_FLOAT: a vector identifier starts the next face *)
                let index_follows () = accept st Comma && Expr.float_follows st in
                if index_follows () then begin
                  let tl = peek_loc st in
                  let t = parse_float st in
                  if index_follows () then not_supported tl "three texture indices per face (interpolated textures)";
                  if Float.of_int (int_of_float t) <> t || t < 0. || int_of_float t >= ntex then
                    Error.raise_at tl "texture index %g is out of range: the texture_list has %d" t ntex;
                  int_of_float t
                end
                else -1
              in
              if ntex > 0 then Growable.push ftex tex)
        in
        faces := Some (l, n, Growable.to_array !fv, if ntex > 0 then Growable.to_array !ftex else [||]);
        sections ()
    | Ident "normal_indices" ->
        advance st;
        let nn = match !normals with Some (n, _) -> n | None -> Error.raise_at l "normal_indices before normal_vectors" in
        nidx := Some (index_block "normal_indices" l nn "normal");
        sections ()
    | Ident "uv_indices" ->
        advance st;
        if !uvidx <> None then Error.raise_at l "only one uv_indices section is allowed in mesh2";
        (* without uv_vectors there is one UV coordinate, (0, 0) *)
        let nu = match !uvs with Some (n, _) when n > 0 -> n | Some _ | None -> 1 in
        uvidx := Some (index_block "uv_indices" l nu "UV");
        sections ()
    | Ident "inside_vector" -> advance st; inside := Some (parse_vector st); sections ()
    | _ -> ()
  in
  sections ();
  let nv, vs = match !vertices with Some v -> v | None -> Error.raise_at loc "mesh2 needs vertex_vectors" in
  let fl, nf, fv, ftex = match !faces with Some f -> f | None -> Error.raise_at loc "mesh2 needs face_indices" in
  let nn, ns = match !normals with Some n -> n | None -> (0, [||]) in
  (* §2.6: without normal_indices the face indices serve when there are as many normals as vertices;
     only the first faces, as many as there are normal indices, can be smooth *)
  let fn =
    match !nidx with
    | Some (nl, n, ni) ->
        if n > nf then Error.raise_at nl "normal_indices has %d entries but there are only %d faces" n nf;
        Array.init (3 * nf) (fun i -> if i < 3 * n then ni.(i) else -1)
    | None ->
        if nn = 0 then [||]
        else if nn = nv then fv
        else
          Error.raise_at fl "normal_vectors has %d entries and vertex_vectors %d: without normal_indices they must be as many" nn nv
  in
  (* Parse_Mesh2: the faces' UV indices are uv_indices, else the face indices when there are as
     many UV vectors as vertices, else every corner has the only UV coordinate (or (0, 0)) *)
  let uvs, fuv =
    let uvs = match !uvs with Some (n, u) when n > 0 -> u | Some _ | None -> [||] in
    let nu = Array.length uvs / 2 in
    match !uvidx with
    | Some (ul, n, ui) ->
        if n <> nf then Error.raise_at ul "uv_indices has %d entries but there are %d faces: they must be as many" n nf;
        (uvs, ui)
    | None ->
        if nu = nv then (uvs, fv)
        else if nu <= 1 then (uvs, [||])
        else Error.raise_at fl "uv_vectors has %d entries and vertex_vectors %d: without uv_indices they must be as many" nu nv
  in
  let mesh = Mesh.build_uv ~uvs ~fuv ~vertices:vs ~vertex_normals:ns ~fv ~fn ~ftex ~corners:None ~inside_vector:!inside in
  Scene.Mesh { mesh; trans = None; textures = !textures }
