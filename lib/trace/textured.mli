(** The colour of a hit whose texture is more than one plain layer (POV-Ray's ComputeTextureColour
    and ComputeOneTextureColour, docs/textures.md): the walk through patterned textures, material
    maps, uv_mapping and a CSG's cutaway textures down to the layers, which the tracer lights. *)

type lighted = Context.t -> Hit.t -> Compiled.surface array -> Vec.t -> Scene.warp list list -> Traced.t
(** How the tracer shades the layers of a texture at a hit (ComputeLightedTexture): [lighted ctx h
    layers q warps] is their colour, the top layer first, their patterns evaluated at [q] inside
    the patterned textures [warps] (the outermost first), with what their transmitted and
    reflected rays bring back. *)

val colour : lighted:lighted -> Context.t -> Hit.t -> Traced.t
(** [colour ~lighted ctx h] is the colour of the hit's texture: each texture a patterned texture
    or a material map picks evaluated at the pattern's warped point and blended by the pattern's
    value (or averaged), a uv-mapped one at the hit's (u, v, 0), a cutaway's members' textures
    weighed; the layers found are shaded by [lighted]. *)
