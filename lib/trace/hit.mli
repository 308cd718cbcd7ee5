(** A surface hit being shaded (POV-Ray's Intersection, pbrt's SurfaceInteraction): the ray that
    met it, the point P, the normal N turned toward the ray, and what the layers and entries of its
    texture share. Secondary rays and shadow feelers leave from it. *)

type memo = { mutable seen : (int * Rgb.t) list; on : bool }
(** The light colour cache of a hit (trace.cpp's lightColorCache): each light's colour after its
    shadow feeler, once tested, by light index; with [on] false no cache at all. *)

type lift = { geometric : Vec.t; error : float }
(** The robust mode's way off the surface at a hit: the shape's geometric normal there (the side
    of the surface) and the bound on the error of the hit point ({!Robust.origin}). *)

type t = {
  ray : Ray.t;  (** the ray that met the surface *)
  obj : Compiled.obj;  (** the object hit (a CSG's member, never the CSG) *)
  part : int;  (** the part of it hit (a mesh face, a box side …) *)
  depth : float;  (** how far along the ray *)
  crossing : Crossing.t;
      (** what the shape reported of the crossing (a julia fractal's point and normal, a bicubic
          patch's normal and (u, v), a parametric surface's (u, v)), {!Crossing.none} for the
          other shapes *)
  level : int;  (** its trace level: the ray's, plus one unless the ray was [Continued] (§7) *)
  point : Vec.t;  (** P, where lights are seen from and secondary rays leave *)
  normal : Vec.t;  (** the shape's normal N, turned toward the ray (§3.1) *)
  lift : lift;  (** the robust mode's way off the surface; unused in POV-Ray's mode ({!origin}) *)
  texture : Compiled.texture;  (** the texture seen: a face's, or the interior texture from inside *)
  memo : memo;
      (** its light colour cache: on for a texture of several layers or entries (they share one
          feeler per light), off for a plain texture *)
  mutable pnormal : Vec.t;
      (** the perturbed normal the slope and aoi patterns see, replaced by each normal pattern
          shaded (POV-Ray's Intersection.PNormal); [normal] at first *)
}

val make : Context.t -> Ray.t -> Nearest.found -> level:int -> t
(** [make ctx ray f ~level] is the hit of [ray] that the search [f] found ({!Nearest.search}:
    the object, the part of it and the depth), with the report it kept of the crossing: the point (refined in the robust mode), the normal turned toward the ray
    and the texture the ray sees there (§3.1, docs/textures.md). *)

val origin : Context.t -> t -> Vec.t -> Vec.t
(** [origin ctx h dir] is where a ray in direction [dir] leaves the hit: its point, or in the
    robust mode that point lifted off the surface to the side [dir] goes ({!Robust.origin}). *)

val spawn : Context.t -> t -> Ray.kind -> weight:float -> interiors:int list -> Vec.t -> Ray.t
(** [spawn ctx h kind ~weight ~interiors dir] is the secondary ray of [kind] (reflected,
    transmitted or continued) leaving the hit along [dir] from {!origin}, at the hit's trace
    level, [mirrored] once it or a ray before it was reflected. *)
