using System.Collections.Immutable;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Ppi;

/// <summary>One read job of a <see cref="PpiReadPlan"/>: its items, and the PDU bytes it and its answer take.</summary>
public sealed record PpiReadRequest(ImmutableArray<S7Item> Items)
{
    public int RequestPduLength => S7JobCodec.ItemJobOverhead + (Items.Length * S7Item.EncodedLength);

    public int AnswerPduLength => S7AnswerCodec.ReadAnswerLength(Items);

    public int DataBytes => Items.Sum(i => i.DataLength);
}
