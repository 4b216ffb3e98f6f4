#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# hexstep: writes the C++ register constants (offsets, field shifts/masks, reset values, access
# masks) from the SystemRDL register map. Usage: gen_regs_hpp.py rdl/hexstep.rdl out.hpp
import sys

from systemrdl import RDLCompiler
from systemrdl.node import AddrmapNode, FieldNode, RegfileNode, RegNode


def reg_lines(reg, prefix, indent):
    out = []
    name = prefix + reg.inst_name
    reset = rmask = wmask = w1c = 0
    out.append(f"{indent}constexpr uint32_t {name} = 0x{reg.address_offset:03X};")
    for f in reg.fields():
        m = ((1 << f.width) - 1) << f.low
        r = f.get_property("reset") or 0
        reset |= (r << f.low) & m
        if f.is_sw_readable:
            rmask |= m
        if f.is_sw_writable and f.get_property("onwrite") is None and f.is_sw_readable:
            wmask |= m
        if f.get_property("onwrite") is not None:
            w1c |= m
        fn = f"{name}_{f.inst_name.upper()}"
        out.append(f"{indent}constexpr unsigned {fn}_SHIFT = {f.low};")
        out.append(f"{indent}constexpr uint32_t {fn}_MASK = 0x{m:08X};")
    out.append(f"{indent}constexpr uint32_t {name}_RESET = 0x{reset:08X};")
    out.append(f"{indent}constexpr uint32_t {name}_RMASK = 0x{rmask:08X};  // readable bits")
    out.append(f"{indent}constexpr uint32_t {name}_RWMASK = 0x{wmask:08X};  // read-write bits")
    out.append(f"{indent}constexpr uint32_t {name}_W1CMASK = 0x{w1c:08X};  // write-1-to-clear bits")
    return out


def main():
    src, dst = sys.argv[1], sys.argv[2]
    rdlc = RDLCompiler()
    rdlc.compile_file(src)
    top = rdlc.elaborate().top
    lines = [
        "// SPDX-License-Identifier: Apache-2.0",
        "// Generated from rdl/hexstep.rdl by scripts/gen_regs_hpp.py (`make regs`). Do not edit.",
        "#pragma once",
        "",
        "#include <cstdint>",
        "",
        "namespace hexstep {",
        "namespace regs {",
        "",
    ]
    regs_list = []
    for child in top.children():
        if isinstance(child, RegNode):
            lines += reg_lines(child, "", "")
            regs_list.append(child.inst_name)
            lines.append("")
        elif isinstance(child, RegfileNode):
            n = child.inst_name
            dims = child.array_dimensions or [1]
            lines.append(f"constexpr uint32_t {n}_BASE = 0x{child.raw_address_offset:03X};")
            lines.append(f"constexpr uint32_t {n}_STRIDE = 0x{(child.array_stride or child.size):03X};")
            lines.append(f"constexpr unsigned {n}_COUNT = {dims[0]};")
            lines.append(f"// Registers of one {n} block, offsets relative to {n}_BASE + k * {n}_STRIDE.")
            lines.append(f"namespace {n.lower()} {{")
            sub = []
            for r in child.children():
                if isinstance(r, RegNode):
                    lines += reg_lines(r, "", "")
                    sub.append(r.inst_name)
            lines.append(f"inline constexpr uint32_t kAll[] = {{{', '.join(sub)}}};")
            lines.append(f"}}  // namespace {n.lower()}")
            lines.append("")
    lines.append(f"inline constexpr uint32_t kAll[] = {{{', '.join(regs_list)}}};")
    lines.append(f"constexpr uint32_t kSize = 0x{top.size:X};")
    lines += ["", "}  // namespace regs", "}  // namespace hexstep", ""]
    with open(dst, "w") as fh:
        fh.write("\n".join(lines))


if __name__ == "__main__":
    main()
