# SPDX-License-Identifier: GPL-3.0-or-later
"""Building node materials from a few rules: point attributes, smooth ramps,
colour mixes and arithmetic. Shared by the eroded terrain's material and the
planet's, so both read their attributes and blend alike (and their numpy
twins, used by the POV-Ray export, follow one set of nodes)."""

import bpy


class NodeMaterial:
    """A new node material `name` with its Principled BSDF; each helper adds a
    node at column x (left to right) and row y, and returns its output socket."""

    def __init__(self, name, roughness=0.85):
        self.material = bpy.data.materials.new(name)
        self.material.use_nodes = True
        self.nodes, self.links = self.material.node_tree.nodes, self.material.node_tree.links
        self.bsdf = self.nodes.get("Principled BSDF")
        self.bsdf.inputs["Roughness"].default_value = roughness

    def _node(self, kind, x, y):
        node = self.nodes.new(kind)
        node.location = (x, y)
        return node

    def _feed(self, socket, value):
        """A constant or another node's output into `socket`."""
        if isinstance(value, (int, float, tuple)):
            socket.default_value = value
        else:
            self.links.new(value, socket)

    def attribute(self, name, y, x=-1000):
        """The point attribute `name` (0..1), its Fac."""
        node = self._node("ShaderNodeAttribute", x, y)
        node.attribute_name = name
        return node.outputs["Fac"]

    def ramp(self, fac, lo, hi, y, x=-800):
        """0 below lo, 1 above hi, smooth between (a Map Range, smoothstep)."""
        node = self._node("ShaderNodeMapRange", x, y)
        node.interpolation_type = "SMOOTHSTEP"
        node.inputs["From Min"].default_value, node.inputs["From Max"].default_value = lo, hi
        self._feed(node.inputs["Value"], fac)
        return node.outputs["Result"]

    def mix(self, fac, a, b, y, x=-500):
        """a where fac is 0, b where it is 1 (MixRGB, Mix); a, b: RGBA tuples or sockets."""
        node = self._node("ShaderNodeMixRGB", x, y)
        self._feed(node.inputs["Fac"], fac)
        self._feed(node.inputs["Color1"], a)
        self._feed(node.inputs["Color2"], b)
        return node.outputs["Color"]

    def math(self, operation, a, b, y, x=-650):
        """A Math node (MAXIMUM, MULTIPLY, ADD, ...) of two values or sockets."""
        node = self._node("ShaderNodeMath", x, y)
        node.operation = operation
        self._feed(node.inputs[0], a)
        self._feed(node.inputs[1], b)
        return node.outputs["Value"]

    def object_position(self, y, x=-1200):
        """The shading point in the object's own frame (Texture Coordinate, Object)."""
        return self._node("ShaderNodeTexCoord", x, y).outputs["Object"]

    def vector_math(self, operation, a, y, x=-1000, b=None):
        """A Vector Math node; LENGTH and the like give 'Value', the others 'Vector'."""
        node = self._node("ShaderNodeVectorMath", x, y)
        node.operation = operation
        self._feed(node.inputs[0], a)
        if b is not None:
            self._feed(node.inputs[1], b)
        return node.outputs["Value"] if operation in ("LENGTH", "DOT_PRODUCT", "DISTANCE") else node.outputs["Vector"]

    def separate_z(self, vector, y, x=-1000):
        node = self._node("ShaderNodeSeparateXYZ", x, y)
        self.links.new(vector, node.inputs[0])
        return node.outputs["Z"]

    def base_color(self, colour):
        self.links.new(colour, self.bsdf.inputs["Base Color"])
