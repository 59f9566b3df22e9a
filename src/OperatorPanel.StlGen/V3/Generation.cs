using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Emit;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.V3;

/// <summary>The v3 handler's texts and figures from checked options (<see cref="HandlerGenerator"/> picks it for protocol 3).</summary>
internal static class Generation
{
    public static HandlerGenerationResult Generate(HandlerOptions options)
    {
        var c = new Context(options);
        var program = Builder.Build(options, FixedIdentity(c));
        var stats = Stats(c, program);
        return new HandlerGenerationResult([], program, stats, AwlWriter.Write(program), Symbols.Write(c.Layout), TechnicianNotes.Write(options, stats));
    }

    /// <summary>IDENTIFY bytes 0-15 (docs/protocol.md, 01 IDENTIFY); the rest comes from the CPU when it answers.</summary>
    public static Identity FixedIdentity(Context c)
    {
        var (model, revision) = Identity.CodesOf(c.Options.Cpu);
        var features = (byte)((c.HasStop ? Identity.StopFeature : 0) | (c.HasList ? Identity.ListFeature : 0));
        return new Identity(
            1, model, revision, (byte)c.Options.EffectiveV3WriteMask, features, (byte)c.EndTimeoutMs, (byte)c.Port,
            (byte)c.Shape.RequestBytes, (byte)HandlerShape.MaxData, (byte)c.Shape.ListItems, (byte)c.Shape.ListBytes, (ushort)c.Layout.First,
            (ushort)c.Shape.VBytes, 0, 0, 0, 0, 0);
    }

    /// <summary>A full handler: what the compact one for the same options would take, for the size warning's advice.</summary>
    private static int? CompactInstructions(Context c) =>
        c.HasList ? Builder.Build(c.Options with { Compact = true }, FixedIdentity(new Context(c.Options with { Compact = true }))).InstructionCount : null;

    private static HandlerStats Stats(Context c, StlProgram program)
    {
        var options = c.Options;
        var purposes = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            [options.Names.Panel] = "port set-up, RUN/TERM switching, serves requests a part per scan; call from OB1 every scan",
            [options.Names.Receive] = $"receive message complete, event {c.ReceiveEvent}",
            [options.Names.Transmit] = $"transmit complete, event {c.TransmitEvent}",
        };
        var blocks = program.Blocks.Where(b => b.Kind != StlBlockKind.Organization).Select(b => new HandlerBlock(b.Name, b.NumberText, purposes[b.Name]));
        return new HandlerStats(
            c.Layout.First, c.Layout.LastByte, program.InstructionCount, options.Port, [c.ReceiveEvent, c.TransmitEvent], [.. blocks])
        {
            CopyBytes = c.Shape.ListBytes,
            StopEnabled = c.HasStop,
            Protocol = 3,
            Compact = !c.HasList,
            Size = new HandlerSize(program.InstructionCount, program.Blocks.Sum(b => b.Networks.Length), options.Cpu, CompactInstructions(c)),
        };
    }
}
