using System.Collections.Immutable;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Handler;

/// <summary>Puts the handler's parts together into OB1, one subroutine and three interrupt routines.</summary>
internal static class HandlerBuilder
{
    /// <summary>Builds the program; <paramref name="options"/> must have passed <see cref="Diagnostics.HandlerOptionsCheck"/>.</summary>
    public static StlProgram Build(HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        var c = new HandlerContext(options);
        var sbr = options.EffectiveFirstSubroutine;
        var first = options.EffectiveFirstInterrupt;
        var receive = ImmutableArray.CreateBuilder<StlNetwork>();
        receive.AddRange(ReceivePart.Networks(c));
        receive.AddRange(IdentifyPart.Networks(c));
        receive.AddRange(ReadPart.Entry(c));
        receive.AddRange(WritePart.Entries(c));
        receive.AddRange(ListPart.Define(c));
        receive.AddRange(ListPart.Read(c));
        receive.AddRange(ItemCheckPart.Networks(c));
        receive.AddRange(ReadPart.Reply(c));
        receive.AddRange(ReadPart.BuildLoop(c));
        receive.AddRange(WritePart.Execute(c));
        receive.AddRange(ReplyPart.Networks(c));

        return new StlProgram(
        [
            new StlBlock(StlBlockKind.Organization, "MAIN", 1, "Main program", [$"Operator panel station {options.Station}: keep network 1 in your OB1."], [InitPart.MainCall(c)]),
            new StlBlock(
                StlBlockKind.Subroutine, c.Names.Panel, sbr, "Operator panel: port set-up",
                [$"Freeport on port {c.Port} at RUN, PPI at TERM. Call from OB1 every scan."], [.. InitPart.Subroutine(c)]),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Receive, first, "Operator panel: request received",
                [$"Event {c.ReceiveEvent}: checks the request (docs/protocol.md section 4) and builds the reply in the buffer."], receive.ToImmutable()),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Delay, first + 1, "Operator panel: reply delay",
                [$"Event {HandlerContext.DelayEvent}, timed interrupt 0 (SMB34): sends the reply."], [InterruptParts.Delay(c)]),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Transmit, first + 2, "Operator panel: reply sent",
                [$"Event {c.TransmitEvent}: receive the next request."], [InterruptParts.Transmit(c)]),
        ]);
    }
}
