# SPDX-License-Identifier: GPL-3.0-or-later
"""What the user sees: the properties made from the parameter tables, the
PropertyGroups kept on objects, how settings are laid out, the sidebar panels
and the menus. Imports core, common/ and build/; never an operator (panels
and menus name operators by their id strings)."""
