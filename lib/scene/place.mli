(** Moving shapes: what one [translate], [rotate], [scale], [matrix] or [transform] modifier does
    to a shape (docs/povray-rules.md §14.4), shape by shape as POV-Ray's [Translate], [Rotate], [Scale] and
    [Transform] methods do it. Apply the modifiers one by one in text order. Also pigments, normals and textures moved
    with their object (§14.7), and the whole scene moved, for [--scene-scale] and [--scene-translate]. *)

(** One object modifier. [Scale] vectors arrive with zero components already replaced by 1
    (§14.2); [Transform] carries a matrix or a whole [transform {…}] (inverse already applied). *)
type op = Translate of Vec.t | Rotate of Vec.t | Scale of Vec.t | Transform of Transform.t

val op_transform : op -> Transform.t
(** [op_transform op] is the transform [op] stands for (rotations in degrees, §14.2). *)

val transform_warps : Scene.warp list -> Transform.t -> Scene.warp list
(** [transform_warps ws t] is [ws] with [t] composed into its head transform, or a new head
    transform when the head is a warp (POV-Ray's Transform_Tpattern). *)

val transform_pigment : Scene.pigment -> Transform.t -> Scene.pigment
(** [transform_pigment p t] is [p] with [t] composed after its transform (§14.7, §17.1); a plain colour
    keeps the same colour and records the transform ([Solid_placed]); a uv-mapped pigment is
    unchanged (POV-Ray moves only the wrapper it never warps). *)

val transform_normal : Scene.normal -> Transform.t -> Scene.normal
(** [transform_normal n t] is [n] with [t] composed into its warps ([transform_warps]), or [n]
    itself when it is uv-mapped, as [transform_pigment] for a pigment. *)

val layer : Scene.layer -> op -> Scene.layer
(** [layer l op] is the layer [l] moved by [op]: its pattern pigment's transform gets [op] composed
    after it (§14.7, §17.1), and so does its normal's; a plain colour records the transform. *)

val texture : Scene.texture -> op -> Scene.texture
(** [texture t op] is [t] moved by [op] as POV-Ray's Transform_Textures moves it: every layer (as
    {!layer}), or a patterned texture's own pattern, whose entries live in the space that pattern
    sees. *)

val csg_box : float array option -> op -> float array option
(** [csg_box box op] is a CSG's POV-Ray box (see {!Scene.shape}) after [op]: the extent of its
    corners mapped by [op], as Recompute_BBox makes it ([[||]], unbounded, stays so). *)

val shape : Scene.shape -> op -> Scene.shape
(** [shape s op] is [s] after [op]: baked into a sphere, plane or triangle while it has no
    transform of its own, composed into its transform otherwise (§14.4); a mesh's face textures move with it. A degenerate triangle
    (or a standalone smooth triangle POV-Ray hides) is left as it is. *)

val scene : scale:float -> translate:Vec.t -> Scene.t -> Scene.t
(** [scene ~scale ~translate s] is [s] scaled by [scale] (> 0) about the origin and then moved by
    [translate]: objects, lights and camera, with fade distances scaled, so that it shows the same
    picture. *)
