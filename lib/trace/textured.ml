(* The walk through a texture down to its layers. *)

open Compiled
open Context

let f32 = Precision.f32

type lighted = Context.t -> Hit.t -> surface array -> Vec.t -> Scene.warp list list -> Traced.t

let black = Traced.black

(* ComputeOneTextureColour: a texture's colour at the point [q] where its pigments and normals are
   evaluated ([warps]: the patterned textures it lies in, the outermost first). *)
let rec texture_colour ~(lighted : lighted) ctx (h : Hit.t) tex q warps : Traced.t =
  match tex with
  | Plain s -> lighted ctx h [| s |] q warps
  | Layered ls -> lighted ctx h ls q warps
  | Cutaway -> black (* never inside another texture *)
  | Chosen { cwarp; choose; textures; cwarps } ->
      let tq = cwarp q in
      texture_colour ~lighted ctx h textures.(choose tq) tq (warps @ [ cwarps ])
  | Uv_mapped { uinner; uwarps } -> texture_colour ~lighted ctx h uinner (Shape.uv h.obj h.part h.crossing h.point) (warps @ [ uwarps ])
  | Blended b ->
      let warps = warps @ [ b.nwarps ] in
      let tq = b.warp q in
      if b.average then
        (* ComputeAverageTextureColours: the entries weighed by their values, summed in single
           precision, over the sum of the weights *)
        let acc = ref black and total = ref 0. in
        Array.iteri
          (fun i t ->
            let c = texture_colour ~lighted ctx h t tq warps in
            let v = b.values.(i) in
            let a = !acc in
            acc := { r = f32 (a.r +. f32 (c.r *. v)); g = f32 (a.g +. f32 (c.g *. v)); b = f32 (a.b +. f32 (c.b *. v)); tr = f32 (a.tr +. f32 (c.tr *. v)) };
            total := f32 (!total +. v))
          b.entries;
        let a = !acc and t = !total in
        { r = f32 (a.r /. t); g = f32 (a.g /. t); b = f32 (a.b /. t); tr = f32 (a.tr /. t) }
      else
        let v = b.value { Patterns.normal = h.pnormal; dir = h.ray.dir; uv = Vec.zero } tq in
        let prev, cur = Surfaces.around b.values v in
        let c1 = texture_colour ~lighted ctx h b.entries.(cur) tq warps in
        if prev = cur then c1
        else
          let c2 = texture_colour ~lighted ctx h b.entries.(prev) tq warps in
          (* the map's values are single precision, and so is their difference (the value's own
             distance from the lower one is taken in double) *)
          let v1 = (v -. b.values.(prev)) /. f32 (b.values.(cur) -. b.values.(prev)) in
          let v2 = 1. -. v1 in
          let mix x y = f32 (f32 (v1 *. x) +. f32 (v2 *. y)) in
          { r = mix c1.r c2.r; g = mix c1.g c2.g; b = mix c1.b c2.b; tr = mix c1.tr c2.tr }

let colour ~lighted ctx (h : Hit.t) : Traced.t =
  let sc = ctx.scene in
  (* an object's uv_mapping: every texture is evaluated at the hit's (u, v, 0) *)
  let q = if h.obj.uv_mapped then Shape.uv h.obj h.part h.crossing h.point else h.point in
  match h.texture with
  | Cutaway ->
      (* the textures of the members around the point, weighed *)
      List.fold_left
        (fun (acc : Traced.t) (w, t) ->
          if w < sc.adc_bailout then acc
          else
            let c = texture_colour ~lighted ctx h t q [] in
            { r = f32 (acc.r +. f32 (w *. c.r)); g = f32 (acc.g +. f32 (w *. c.g)); b = f32 (acc.b +. f32 (w *. c.b)); tr = f32 (acc.tr +. f32 (w *. c.tr)) })
        black (Surfaces.cutaway ctx.stack sc h.obj h.point)
  | (Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _) as tex -> texture_colour ~lighted ctx h tex q []
