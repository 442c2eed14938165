"""The small seed scene the scene checks run: A = 1.5 - x on FE_Q(10) x 7
(the receptance of the paper's 4000 linear cells to 1e-10 in the band),
modal receptance, M harmonics, Energy max 1e-3, and the Output entries given."""


def small_seed_scene(output, harmonics=20, omega_max=2.0):
    """The scene text; `output` maps Output entries to values."""
    entries = "".join(f"  set {name} = {value}\n" for name, value in output.items())
    return (f"subsection Discretisation\n  set Degree = 10\n  set Cells = 7\nend\n"
            f"subsection Receptance\n  set Method = modal\nend\n"
            f"subsection Harmonic balance\n  set Harmonics = {harmonics}\nend\n"
            f"subsection Continuation\n  set Omega max = {omega_max}\n  set Energy max = 1e-3\nend\n"
            f"subsection Output\n{entries}end\n")
