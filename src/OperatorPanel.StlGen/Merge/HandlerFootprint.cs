using System.Collections.Immutable;
using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// What the handler for checked <see cref="HandlerOptions"/> reserves, in the terms a user's program could collide with:
/// block numbers and names, interrupt events, the port and its special memory bytes, the V bytes. Protocol 3 has no
/// timed interrupt (docs/protocol.md section 0: the end timer is the reply's earliest start), so event 10 and SMB34 stay
/// the user's there; its blocks are v2's superset (three interrupt numbers kept), its V bytes its own.
/// </summary>
internal sealed class HandlerFootprint
{
    public HandlerFootprint(HandlerOptions options)
    {
        var context = new HandlerContext(options);
        Port = options.Port;
        Subroutine = options.EffectiveFirstSubroutine;
        FirstInterrupt = options.EffectiveFirstInterrupt;
        LastInterrupt = FirstInterrupt + options.InterruptRoutines - 1;
        Names = [.. options.Names.All];
        UsesTimedInterrupt = options.Protocol != 3;
        ReceiveEvent = context.ReceiveEvent;
        TransmitEvent = context.TransmitEvent;
        var layout = context.Layout;
        // Protocol 3 keeps its bytes from V_FIRST (HandlerShape.VBytes of the full or compact shape), not v2's layout.
        (FirstVByte, LastVByte) = options.Protocol == 3
            ? (options.EffectiveV3First, options.EffectiveV3First + (options.Compact ? Core.Protocol.V3.HandlerShape.Compact : Core.Protocol.V3.HandlerShape.Full).VBytes - 1)
            : (layout.BufferStart, layout.LastByte);
        PortControlByte = context.SmPort(30);
        FirstReceiveByte = context.SmPort(86);
        LastReceiveByte = context.SmPort(94);
    }

    public int Port { get; }

    public int Subroutine { get; }

    public int FirstInterrupt { get; }

    public int LastInterrupt { get; }

    public ImmutableArray<string> Names { get; }

    public int ReceiveEvent { get; }

    public int TransmitEvent { get; }

    /// <summary>Receive character, event 8 (port 0) / 25 (port 1): attached by a user means Freeport on this port.</summary>
    public int ReceiveCharacterEvent => Port == 0 ? 8 : 25;

    /// <summary>Timed interrupt 0 (event 10, SMB34) makes v2's reply delay; a v3 handler leaves both to the user.</summary>
    public bool UsesTimedInterrupt { get; }

    public ImmutableArray<int> Events => UsesTimedInterrupt ? [ReceiveEvent, HandlerContext.DelayEvent, TransmitEvent] : [ReceiveEvent, TransmitEvent];

    public int FirstVByte { get; }

    public int LastVByte { get; }

    public int VBytes => LastVByte - FirstVByte + 1;

    /// <summary>SMB30 or SMB130 (seed 002 Table C-11).</summary>
    public int PortControlByte { get; }

    /// <summary>SMB86 / SMB186 ... SMB94 / SMB194, receive status and set-up (seed 002 Table C-16).</summary>
    public int FirstReceiveByte { get; }

    public int LastReceiveByte { get; }

    /// <summary>SMB34, the interval of timed interrupt 0 that makes the reply delay.</summary>
    public const int ReplyDelayByte = 34;

    public string VRange => $"VB{FirstVByte}-VB{LastVByte}";

    public string EventPurpose(int number) =>
        number == ReceiveEvent ? $"receive message complete on port {Port}"
        : number == TransmitEvent ? $"transmit complete on port {Port}"
        : "timed interrupt 0, the reply delay";
}
