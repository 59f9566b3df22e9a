using System.Collections.Immutable;

namespace OperatorPanel.TestKit;

/// <summary>A line of a script: what the PC writes ("&gt;"), what it then reads ("&lt;"), or a read that times out.</summary>
internal sealed record ScriptStep(ScriptStepKind Kind, ImmutableArray<ScriptElement> Elements, int LineNumber, string Text);

internal enum ScriptStepKind
{
    Request,
    Response,
    NoResponse,
}
