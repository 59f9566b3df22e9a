using System.Diagnostics.CodeAnalysis;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Emit;
using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen;

/// <summary>Generates the PLC side of docs/protocol.md for one station: check the options, build the model, write the texts.</summary>
public static class HandlerGenerator
{
    public static HandlerGenerationResult Generate(HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        var diagnostics = HandlerOptionsCheck.Check(options);
        if (!diagnostics.IsEmpty)
        {
            return new HandlerGenerationResult(diagnostics, null, null, string.Empty, string.Empty, string.Empty);
        }

        if (options.Protocol == 3)
        {
            return V3.Generation.Generate(options);
        }

        var program = HandlerBuilder.Build(options);
        var stats = StatsOf(options, program);
        var layout = new HandlerLayout(options.EffectiveBufferStart, options.CopyBytes);
        return new HandlerGenerationResult(
            diagnostics, program, stats, AwlWriter.Write(program), SymbolTableWriter.Write(layout), TechnicianNotes.Write(options, stats));
    }

    /// <summary>Just the .awl text, or the diagnostics as one message: what a simulated station needs.</summary>
    public static bool TryGenerateAwl(HandlerOptions options, [NotNullWhen(true)] out string? awlText, [NotNullWhen(false)] out string? error)
    {
        var generated = Generate(options);
        if (!generated.Ok)
        {
            (awlText, error) = (null, $"the handler cannot be generated: {string.Join("; ", generated.Diagnostics)}");
            return false;
        }

        (awlText, error) = (generated.AwlText, null);
        return true;
    }

    private static HandlerStats StatsOf(HandlerOptions options, StlProgram program)
    {
        var context = new HandlerContext(options);
        var purposes = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            [options.Names.Panel] = "port set-up, RUN/TERM switching, serves requests a part per scan; call from OB1 every scan",
            [options.Names.Receive] = $"receive message complete, event {context.ReceiveEvent}",
            [options.Names.Delay] = $"reply delay, event {HandlerContext.DelayEvent} (timed interrupt 0)",
            [options.Names.Transmit] = $"transmit complete, event {context.TransmitEvent}",
        };
        var blocks = program.Blocks.Where(b => b.Kind != StlBlockKind.Organization)
            .Select(b => new HandlerBlock(b.Name, b.NumberText, purposes[b.Name]));
        var layout = context.Layout;
        var networks = program.Blocks.Sum(b => b.Networks.Length);
        return new HandlerStats(
            layout.BufferStart, layout.LastByte, program.InstructionCount, options.Port,
            [context.ReceiveEvent, HandlerContext.DelayEvent, context.TransmitEvent], [.. blocks])
        {
            CopyBytes = options.CopyBytes,
            ChangesWorkBytes = HandlerLayout.ChangesBytes,
            StopEnabled = options.AllowStop,
            Size = new HandlerSize(program.InstructionCount, networks, options.Cpu),
        };
    }
}
