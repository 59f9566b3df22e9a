namespace OperatorPanel.Core.Tests.Writes;

/// <summary>What <see cref="ReplyLosingLink"/> does to the next write.</summary>
internal enum WriteFate
{
    /// <summary>The PLC applies it; its reply is lost.</summary>
    AppliedReplyLost,

    /// <summary>The PLC applies it, but its reply's REQCHECK shows it acted on a corrupted copy.</summary>
    AppliedToCorruptedCopy,

    /// <summary>The request is lost on the way: nothing applied, no reply.</summary>
    RequestLost,

    /// <summary>The port could not be opened: nothing left the PC.</summary>
    NeverSent,
}
