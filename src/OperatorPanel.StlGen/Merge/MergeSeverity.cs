namespace OperatorPanel.StlGen.Merge;

/// <summary>Whether a merge finding stops the merge.</summary>
public enum MergeSeverity
{
    /// <summary>A collision or an unreadable program: nothing is written.</summary>
    Error,

    /// <summary>Something that cannot be checked from the text alone; the merge goes ahead.</summary>
    Warning,
}
