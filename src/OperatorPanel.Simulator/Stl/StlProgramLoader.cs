using System.Collections.Immutable;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Checks;
using OperatorPanel.Stl.Symbols;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Checks a parsed .awl program against a CPU (<see cref="AwlProgramCheck"/>: what Micro/WIN refuses) and compiles it
/// for <see cref="StlPlc"/>. Every instruction the
/// simulator does not implement, every operand outside the CPU's ranges and every unknown block name is reported
/// with its line ("line 57: BIR is not implemented by the simulator"); a program with any of them is not returned.
/// </summary>
public static class StlProgramLoader
{
    /// <summary>Parses and loads .awl text; parse and load diagnostics come back together, in line order.</summary>
    public static StlLoadResult Load(string awlText, CpuProfile cpu, StlLoadOptions? options = null)
    {
        var parsed = AwlParser.Parse(awlText);
        var loaded = Load(parsed.Program, cpu, options);
        return parsed.Succeeded
            ? loaded
            : new StlLoadResult(null, [.. parsed.Diagnostics.Concat(loaded.Diagnostics).OrderBy(d => d.Line)]) { Warnings = loaded.Warnings };
    }

    public static StlLoadResult Load(AwlProgram program, CpuProfile cpu, StlLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(program);
        ArgumentNullException.ThrowIfNull(cpu);
        options ??= StlLoadOptions.Default;
        var diagnostics = new List<AwlDiagnostic>();
        var warnings = new List<AwlDiagnostic>();
        var unknownSymbols = ImmutableArray<AwlDiagnostic>.Empty;
        if (options.Symbols is { } symbols)
        {
            (program, unknownSymbols) = AwlSymbolResolver.Resolve(program, symbols);
        }

        // What Micro/WIN's import would refuse in the file's structure does not stop a run: the interpreter can still
        // run a program whose OB1 header lacks its name. A CALL to a missing block and a block defined twice the
        // compiler refuses itself; a block without body (a protected POU) runs as an empty one, with a warning.
        var export = AwlExportCheck.Check(program);
        warnings.AddRange(export.Warnings);
        warnings.AddRange(export.Refusals.Where(r => r.Id == AwlCheckIds.BlockHeaderWithoutName)
            .Select(r => r with { Message = $"Micro/WIN would refuse this file: {r.Message}" }));
        var refusals = AwlProgramCheck.Check(program, cpu);
        var ordered = program.Blocks.Where(b => b.Kind == AwlBlockKind.OrganizationBlock)
            .Concat(program.Blocks.Where(b => b.Kind != AwlBlockKind.OrganizationBlock)).ToArray();
        var blocks = ordered.Select((b, i) => new StlBlock(b, i)).ToArray();
        CheckBlocks(blocks, cpu, diagnostics);
        var names = NameBlocks(blocks, diagnostics);
        var locals = blocks.Select(b => StlLocalLayout.Place(b, cpu.LocalBytesPerPou, diagnostics)).ToArray();
        var compiler = new StlBlockCompiler(cpu, names, diagnostics, warnings, options);
        foreach (var block in blocks)
        {
            block.Ops = compiler.Compile(block, locals[block.Index]);
        }

        // What Micro/WIN refuses is said once, by the program check, and a symbol missing from the table once, by the
        // resolver; the compiler's word on the same line goes.
        diagnostics.RemoveAll(d => refusals.Concat(unknownSymbols).Any(r => r.Line == d.Line));
        diagnostics.AddRange(refusals);
        diagnostics.AddRange(unknownSymbols);
        var loaded = diagnostics.Count == 0 ? new StlProgram(cpu, blocks, compiler.EdgeCount) : null;
        return new StlLoadResult(loaded, [.. diagnostics.OrderBy(d => d.Line)]) { Warnings = [.. warnings.OrderBy(w => w.Line)] };
    }

    private static void CheckBlocks(StlBlock[] blocks, CpuProfile cpu, List<AwlDiagnostic> diagnostics)
    {
        var mains = blocks.Count(b => b.Kind == AwlBlockKind.OrganizationBlock);
        if (mains != 1)
        {
            diagnostics.Add(new AwlDiagnostic(blocks.Length > 1 ? blocks[1].Source.StartLine : 1,
                mains == 0 ? "the program has no ORGANIZATION_BLOCK (OB1)" : "the program has more than one ORGANIZATION_BLOCK"));
        }

        foreach (var block in blocks)
        {
            var limit = block.Kind switch
            {
                AwlBlockKind.Subroutine => cpu.Subroutines,
                AwlBlockKind.InterruptRoutine => cpu.InterruptRoutines,
                AwlBlockKind.OrganizationBlock => 2,
            };
            if (block.Source.Number >= limit || (block.Kind == AwlBlockKind.OrganizationBlock && block.Source.Number != 1))
            {
                diagnostics.Add(new AwlDiagnostic(block.Source.StartLine,
                    $"{block.Name}: {block.Source.DefaultName} is outside the {cpu.Name}'s block numbers"));
            }
        }
    }

    private static Dictionary<string, StlBlock> NameBlocks(StlBlock[] blocks, List<AwlDiagnostic> diagnostics)
    {
        var names = new Dictionary<string, StlBlock>(StringComparer.OrdinalIgnoreCase);
        foreach (var block in blocks)
        {
            if (!names.TryAdd(block.Name, block) && names[block.Name].Name.Equals(block.Name, StringComparison.OrdinalIgnoreCase))
            {
                diagnostics.Add(new AwlDiagnostic(block.Source.StartLine, $"block name {block.Name} is used twice"));
            }
        }

        foreach (var block in blocks)
        {
            // The default names (SBR_3, INT_0) and the numbers exports write (SBR3, INT0) reach a block too, unless
            // another block carries that name.
            names.TryAdd(block.Source.DefaultName, block);
            names.TryAdd(block.Source.NumberName, block);
        }

        var numbers = blocks.GroupBy(b => b.Source.DefaultName, StringComparer.OrdinalIgnoreCase).Where(g => g.Count() > 1);
        foreach (var duplicate in numbers)
        {
            diagnostics.Add(new AwlDiagnostic(duplicate.Last().Source.StartLine, $"{duplicate.Key} is defined twice"));
        }

        return names;
    }
}
